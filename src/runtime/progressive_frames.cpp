#include "runtime/progressive_frames.h"

namespace relight {

namespace {

// Puts the relighter back to converged light, however the frames end.
class ConvergedOnExit {
 public:
  explicit ConvergedOnExit(RelitScene& relit) : relit_(relit) {}
  ConvergedOnExit(const ConvergedOnExit&) = delete;
  ConvergedOnExit& operator=(const ConvergedOnExit&) = delete;
  ~ConvergedOnExit() {
    relit_.set_material_bounces(-1);
    relit_.relighter().set_layout_bounce(true);
  }

 private:
  RelitScene& relit_;
};

}  // namespace

int show_progressively(RelitScene& relit, const LightingState& state,
                       const std::function<void(bool converged)>& frame) {
  const ConvergedOnExit restore(relit);
  const bool material_edit = relit.state().materials != state.materials;
  relit.relighter().set_layout_bounce(false);
  if (material_edit) relit.set_material_bounces(0);
  relit.apply(state);
  const bool converged = !material_edit && relit.relighter().layout_converged();
  frame(converged);
  if (converged) return 1;
  relit.set_material_bounces(-1);
  relit.relighter().set_layout_bounce(true);
  relit.apply(state);
  frame(relit.relighter().layout_converged());
  return 2;
}

}  // namespace relight
