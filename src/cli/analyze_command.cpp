// `relight analyze SCENE.rlt --sh-energy [-o FILE.csv]`: analyses of a precomputed file.
// --sh-energy (the only one so far): per portal and colour channel, how much each SH order
// of the stored indirect transfer can carry (Yue et al. 2009's Eq. 4–5 and
// Figure 8; sources/portals/sh_energy.h), as a table on stdout and optionally a CSV
// `portal,l,channel,energy,share,cumulative,shell_energy` (with the energy per order of the
// shell the relighter projects for the scene's state).
#include <array>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "sources/portals/portal_lighting.h"
#include "sources/portals/sh_energy.h"
#include "sources/transfer_file.h"

namespace relight {

namespace {

struct AnalyzeArgs {
  std::string rlt, output;
  bool sh_energy = false;
};

struct PortalEnergy {
  std::string name;
  std::vector<ShOrderEnergy> orders;
  std::vector<std::array<double, 3>> shell;  // per order: Σ_m c_lm² of the scene's shell
};

constexpr const char* kChannelNames[3] = {"r", "g", "b"};

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

std::string sh_energy_csv(const std::vector<PortalEnergy>& portals) {
  std::string csv = "portal,l,channel,energy,share,cumulative,shell_energy\n";
  for (const PortalEnergy& p : portals) {
    for (const ShOrderEnergy& o : p.orders) {
      for (std::size_t c = 0; c < 3; ++c) {
        char line[200];
        std::snprintf(line, sizeof line, ",%d,%s,%.9g,%.9g,%.9g,%.9g\n", o.l, kChannelNames[c],
                      o.energy[c], o.share[c], o.cumulative[c],
                      p.shell[static_cast<std::size_t>(o.l)][c]);
        csv += csv_cell(p.name) + line;
      }
    }
  }
  return csv;
}

void print_sh_energy(std::ostream& out, const PortalEnergy& p, std::size_t vertices, int sh_order) {
  out << "portal \"" << p.name << "\": indirect SH transfer (interreflected light; the direct "
      << "part is stored as cubemaps), " << vertices << " vertices, orders l < " << sh_order << "\n"
      << "energy: max over unit order-l shell coefficients of the mean square vertex response "
      << "(Eq. 4-5)\n";
  char line[200];
  std::snprintf(line, sizeof line, "%3s %11s %11s %11s %8s %8s %8s %8s %8s %8s\n", "l", "energy R",
                "energy G", "energy B", "share R", "share G", "share B", "cum R", "cum G", "cum B");
  out << line;
  for (const ShOrderEnergy& o : p.orders) {
    std::snprintf(line, sizeof line,
                  "%3d %11.4g %11.4g %11.4g %7.2f%% %7.2f%% %7.2f%% %7.2f%% %7.2f%% %7.2f%%\n", o.l,
                  o.energy[0], o.energy[1], o.energy[2], 100 * o.share[0], 100 * o.share[1],
                  100 * o.share[2], 100 * o.cumulative[0], 100 * o.cumulative[1],
                  100 * o.cumulative[2]);
    out << line;
  }
  out << "shell of the scene's state (sky and ground; a sun behind clear glass is traced "
      << "exactly and is not in it): sum over m of c_lm^2 per order, (cd/m2)^2\n";
  std::snprintf(line, sizeof line, "%3s %11s %11s %11s\n", "l", "shell R", "shell G", "shell B");
  out << line;
  for (std::size_t l = 0; l < p.shell.size(); ++l) {
    std::snprintf(line, sizeof line, "%3zu %11.4g %11.4g %11.4g\n", l, p.shell[l][0], p.shell[l][1],
                  p.shell[l][2]);
    out << line;
  }
}

int run_analyze(const AnalyzeArgs& args) {
  if (!args.sh_energy) {
    fail_input("relight analyze", "choose an analysis: --sh-energy (the only one so far)");
  }
  const TransferFile t = open_transfer_file(args.rlt);
  if (t.view.portals.empty()) {
    fail_input(args.rlt, "the scene has no portals: --sh-energy analyses portal transfer");
  }
  std::vector<PortalEnergy> portals;
  for (std::size_t p = 0; p < t.view.portals.size(); ++p) {
    const PortalTransferView& view = t.view.portals[p];
    // The shell as the relighter renders it for the scene's own state.
    PortalLighting lighting;
    update_portal_lighting(lighting, static_cast<std::uint32_t>(p), view, t.view.portal_sh_order,
                           portal_state(t.scene.portals[p], t.scene.exterior.size()), t.scene);
    portals.push_back(
        {view.name,
         portal_sh_energy(view, t.vertex_count, t.view.receivers, t.view.portal_sh_order),
         shell_order_energy(lighting.shell.sh, t.view.portal_sh_order)});
    if (portals.size() > 1) std::cout << "\n";
    print_sh_energy(std::cout, portals.back(), t.vertex_count, t.view.portal_sh_order);
  }
  if (!args.output.empty()) {
    write_text_atomically(args.output, sh_energy_csv(portals));
    std::cout << "wrote " << args.output << "\n";
  }
  return 0;
}

}  // namespace

void add_analyze_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand("analyze", "Analyses of a precomputed scene");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_flag("--sh-energy", args->sh_energy,
                "per portal, order and channel: the most energy each SH order of the indirect "
                "transfer can carry (interior-scene paper Eq. 4-5, Figure 8)");
  cmd->add_option("-o,--output", args->output,
                  "CSV to write: portal,l,channel,energy,share,"
                  "cumulative");
  cmd->callback([args, &action] { action = [args] { return run_analyze(*args); }; });
}

}  // namespace relight
