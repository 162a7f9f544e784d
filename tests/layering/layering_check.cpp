#include "layering_check.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace relight::layering {

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string library_name(const std::string& folder) {
  std::string name = "relight_" + folder;
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

// The stage a path under src/ belongs to: the longest stage folder that contains it.
int stage_of(const std::vector<Stage>& stages, const std::string& path) {
  int best = -1;
  std::size_t best_length = 0;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const std::string prefix = stages[i].folder + "/";
    if (path.compare(0, prefix.size(), prefix) == 0 && prefix.size() > best_length) {
      best = static_cast<int>(i);
      best_length = prefix.size();
    }
  }
  return best;
}

}  // namespace

std::vector<Stage> read_stages(const fs::path& cmake_lists) {
  const std::string text = read_text(cmake_lists);
  std::vector<Stage> stages;
  std::vector<std::string> names;
  const std::regex call(R"(\nrelight_stage\(([^)]*)\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator();
       ++it) {
    std::istringstream words((*it)[1].str());
    Stage s;
    words >> s.folder;
    std::string word;
    while (words >> word) {
      const auto known = std::find(names.begin(), names.end(), word);
      if (known != names.end()) {
        s.links.push_back(stages[static_cast<std::size_t>(known - names.begin())].folder);
      } else if (word.rfind("relight_", 0) == 0 && word != "relight_websocket") {
        s.links.push_back("?" + word);  // a stage not (yet) declared: later or unknown
      }
    }
    names.push_back(library_name(s.folder));
    stages.push_back(std::move(s));
  }
  const std::regex never(R"(\nrelight_stage_never_includes\(([^)]*)\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), never);
       it != std::sregex_iterator(); ++it) {
    std::istringstream words((*it)[1].str());
    std::string folder, other;
    words >> folder;
    const auto stage = std::find_if(stages.begin(), stages.end(),
                                    [&](const Stage& s) { return s.folder == folder; });
    if (stage == stages.end()) throw std::runtime_error("never_includes names no stage: " + folder);
    while (words >> other) stage->never_includes.push_back(other);
  }
  return stages;
}

std::vector<std::string> documented_stage_order(const fs::path& architecture_md) {
  std::istringstream in(read_text(architecture_md));
  std::string line;
  bool in_section = false, in_block = false;
  std::vector<std::string> order;
  const std::regex entry(R"(^src/([a-z_/]+)/\s)");
  while (std::getline(in, line)) {
    if (!in_section) {
      in_section = line == "## Stages";
      continue;
    }
    if (line.rfind("```", 0) == 0) {
      if (in_block) break;
      in_block = true;
      continue;
    }
    std::smatch m;
    const std::string padded = line + " ";
    if (in_block && std::regex_search(padded, m, entry)) order.push_back(m[1].str());
  }
  return order;
}

std::vector<std::string> layering_violations(const fs::path& root) {
  const std::vector<Stage> stages = read_stages(root / "CMakeLists.txt");
  std::vector<std::string> out;
  std::vector<std::set<int>> included(stages.size());
  const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)")re");
  const fs::path src = root / "src";
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".h" || ext == ".cpp")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const std::string relative = fs::relative(file, src).generic_string();
    const int own = stage_of(stages, relative);
    if (own < 0) {
      if (relative.find('/') != std::string::npos) {
        out.push_back("src/" + relative + ": in no stage of CMakeLists.txt");
      }
      continue;  // src/main.cpp: the executable, above every stage
    }
    std::istringstream in(read_text(file));
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      std::smatch m;
      if (!std::regex_search(line, m, include_line)) continue;
      const std::string header = m[1].str();
      if (header.find('/') == std::string::npos) continue;  // a header beside the file
      const int theirs = stage_of(stages, header);
      const std::string where = "src/" + relative + ":" + std::to_string(number) + ": ";
      if (theirs < 0) {
        out.push_back(where + "includes \"" + header + "\", which is in no stage");
      } else if (theirs > own) {
        out.push_back(where + "includes \"" + header + "\" of stage " +
                      stages[static_cast<std::size_t>(theirs)].folder + ", which comes after " +
                      stages[static_cast<std::size_t>(own)].folder);
      } else if (theirs != own) {
        included[static_cast<std::size_t>(own)].insert(theirs);
      }
      const std::string& their_folder = stages[static_cast<std::size_t>(theirs)].folder;
      for (const std::string& banned : stages[static_cast<std::size_t>(own)].never_includes) {
        if (their_folder == banned || their_folder.rfind(banned + "/", 0) == 0) {
          out.push_back(where + "includes \"" + header + "\" of stage " + their_folder +
                        ", which " + stages[static_cast<std::size_t>(own)].folder +
                        " never includes");
        }
      }
    }
  }
  // Links: only earlier stages the stage includes; every included stage reachable.
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < stages.size(); ++i) index[stages[i].folder] = static_cast<int>(i);
  for (std::size_t i = 0; i < stages.size(); ++i) {
    for (const std::string& link : stages[i].links) {
      const auto it = index.find(link);
      if (it == index.end()) {
        out.push_back("CMakeLists.txt: " + stages[i].folder + " links " + link.substr(1) +
                      ", no earlier stage");
      } else if (!included[i].count(it->second)) {
        out.push_back("CMakeLists.txt: " + stages[i].folder + " links " + link +
                      " but includes nothing of it");
      }
    }
    for (const int needed : included[i]) {
      std::set<int> reached;
      std::vector<int> todo{static_cast<int>(i)};
      while (!todo.empty()) {
        const int s = todo.back();
        todo.pop_back();
        for (const std::string& link : stages[static_cast<std::size_t>(s)].links) {
          const auto it = index.find(link);
          if (it != index.end() && reached.insert(it->second).second) todo.push_back(it->second);
        }
      }
      if (!reached.count(needed)) {
        out.push_back("CMakeLists.txt: " + stages[i].folder + " includes " +
                      stages[static_cast<std::size_t>(needed)].folder +
                      " but does not link it, directly or through another stage");
      }
    }
  }
  return out;
}

}  // namespace relight::layering
