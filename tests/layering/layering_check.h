// The layering rule (docs/architecture.md, "Stages"): the stages are the relight_stage()
// calls of CMakeLists.txt, in that order; a file of a stage includes headers of its own
// stage and earlier ones only, and a stage's library links only earlier stages that its
// files include, while every stage it includes is reachable through what it links.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace relight::layering {

struct Stage {
  std::string folder;              // under src/, e.g. "sources/portals"
  std::vector<std::string> links;  // folders of the stages its library links
  // Earlier stage folders it must not include all the same (relight_stage_never_includes),
  // each with the stages under it: "sources" covers "sources/portals".
  std::vector<std::string> never_includes;
};

// The stages in order, read from the relight_stage() calls of `cmake_lists`, with the
// relight_stage_never_includes() rules of each.
std::vector<Stage> read_stages(const std::filesystem::path& cmake_lists);

// The stage folders named in order by the lines `src/<folder>/` that open the lines of the
// first fenced block after the heading "## Stages" of `architecture_md`.
std::vector<std::string> documented_stage_order(const std::filesystem::path& architecture_md);

// Every breach of the rule in the tree at `root` (CMakeLists.txt and src/), one line each:
// "src/FILE:LINE: ..." for an include (of a later stage, or of one its stage never includes),
// "CMakeLists.txt: ..." for a link.
std::vector<std::string> layering_violations(const std::filesystem::path& root);

}  // namespace relight::layering
