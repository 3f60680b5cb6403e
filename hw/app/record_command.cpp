// `oasis-go1 record`: write frames from a source to a recording folder, for replay and for
// tests. Nothing is sent to a robot; the synthetic world's robot stands still.

#include <iostream>
#include <memory>
#include <string>
#include <variant>

#include "app/commands.hpp"
#include "camera/recording_writer.hpp"
#include "command_line/number_options.hpp"
#include "loop/robot_link.hpp"
#include "loop/session.hpp"
#include "settings/settings.hpp"

namespace oasis::hw::app {
namespace {

struct RecordRequest {
  std::string config;
  std::string source = "synthetic";
  std::string folder;
  std::uint64_t frames = 50;
  bool replace = false;
};

int record(const RecordRequest& request) {
  settings::Go1Settings settings = loop::settings_or_defaults(request.config);
  settings.source = loop::source_option(request.source);
  const loop::SessionCatalog catalog(settings.loop.catalog, settings.loop.catalog_spec);
  loop::DryRunLink standing;
  loop::SessionSource source = loop::open_source(settings, catalog.view(), standing);
  camera::RecordingWriter writer(request.folder, request.replace ? camera::ExistingFolder::kReplace
                                                                 : camera::ExistingFolder::kRefuse);
  for (std::uint64_t k = 0; k < request.frames; ++k) {
    NextFrame next = source.source->next();
    if (const SourceStop* stop = std::get_if<SourceStop>(&next)) {
      if (stop->kind == SourceStop::Kind::kFailure) throw loop::SetupError(stop->reason);
      break;
    }
    writer.write(std::get<Frame>(next),
                 source.true_holder ? source.true_holder() : std::optional<TreatHolder>{});
  }
  writer.finish();
  std::cerr << "oasis-go1: wrote " << writer.frames_written() << " frames to " << request.folder
            << '\n';
  return 0;
}

}  // namespace

CommandRunner add_record_command(CLI::App& app) {
  auto request = std::make_shared<RecordRequest>();
  CLI::App* command =
      app.add_subcommand("record", "write frames from a source into a recording folder");
  command->add_option("folder", request->folder, "the recording's folder (created)")->required();
  command->add_option("--source", request->source, "synthetic (default) or camera");
  command->add_option("--frames", request->frames, "how many frames (default 50)")
      ->check(oasis::cli::whole_in(1, 100000));
  command->add_option("--config", request->config, "YAML settings (camera, perception)")
      ->check(CLI::ExistingFile);
  command->add_flag("--replace", request->replace, "replace an earlier recording in the folder");
  return [request] { return record(*request); };
}

}  // namespace oasis::hw::app
