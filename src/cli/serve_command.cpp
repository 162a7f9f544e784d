// `relight serve SCENE.rlt [--host 127.0.0.1] [--port 8080] [--client DIR] [--photometry DIR]
// [--models DIR]`: the studio (docs/studio.md) on a precomputed scene: prints the URL to open
// and serves until Ctrl-C, and serves a model opened in the studio next.
// The protocol is docs/studio-protocol.md; the server serve/studio_server.h.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/serve_run.h"

namespace relight {

void add_serve_command(CLI::App& app, Action& action) {
  auto rlt = std::make_shared<std::string>();
  auto options = std::make_shared<StudioOptions>();
  auto client = std::make_shared<std::string>();
  auto photometry = std::make_shared<std::string>();
  auto models = std::make_shared<std::string>();
  CLI::App* cmd =
      app.add_subcommand("serve", "Serve the studio (a browser client) on a precomputed scene");
  cmd->add_option("scene", *rlt, "precomputed scene (.rlt)")->required();
  add_studio_address_options(*cmd, *options);
  cmd->add_option("--client", *client, "folder of the studio client (default: the source tree's)");
  cmd->add_option("--photometry", *photometry,
                  "folder of IES/LDT files for the studio's catalogue (uploads go to its "
                  "uploads/ folder)");
  cmd->add_option("--models", *models,
                  "folder where the studio's \"Open model…\" keeps imported and precomputed "
                  "models (default: models/ beside SCENE.rlt)");
  cmd->callback([rlt, options, client, photometry, models, &action] {
    action = [rlt, options, client, photometry, models] {
      options->client = *client;
      options->photometry = *photometry;
      options->models = *models;
      return serve_studio(*rlt, *options);
    };
  });
}

}  // namespace relight
