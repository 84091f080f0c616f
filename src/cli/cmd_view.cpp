// citylangsplat view: a local web viewer with live text queries (src/viewer, docs/viewer.md).
#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "language/language_model.h"
#include "viewer/viewer_model.h"
#include "viewer/viewer_server.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_view(int argc, char** argv) {
  Args args("view",
            "Serve a trained model in the browser: the Gaussians in a WebGL splat renderer, the scene's cameras\n"
            "(click one to see its photo), a text box whose queries recolour the Gaussians by relevance and list\n"
            "the city objects (CityGML/CityJSON ids) that answer, and the city model's triangles on request.\n"
            "Prints the URL; Ctrl-C stops. See docs/viewer.md.");
  fs::path out, assets = CLS_WEB_ASSETS, vendor = CLS_WEB_VENDOR;
  int port = 8080;
  std::string host = "127.0.0.1", method = "citylangsplat", scene;
  args.positional("OUT", out, "a `run` output directory or a language model directory (model.json)")
      .bind("port", port, "TCP port (0: any free port)")
      .bind("host", host, "address to bind; anything but loopback makes the model readable from the network")
      .bind("method", method, "which language model of a run directory: citylangsplat or langsplat")
      .bind("scene", scene, "scene directory for cameras and photos (empty: the run's, or the one recorded with the model)")
      .bind("assets", assets, "the page's folder (web/viewer of the source tree)")
      .bind("vendor", vendor, "npm's node_modules with three and the splat renderer (scripts/install_web.sh)");
  if (!args.parse(argc, argv)) return 0;

  if (!fs::is_directory(out)) fail(out.string(), "not a directory (a `run` output or a language model)");
  if (!fs::exists(assets / "index.html")) fail((assets / "index.html").string(), "missing (--assets: web/viewer)");
  if (!fs::is_directory(vendor / "three"))
    fail((vendor / "three").string(), "missing: install the page's npm packages with `bash scripts/install_web.sh`");
  if (port < 0 || port > 65535) throw UsageError("view: --port must be 0..65535");
  if (host != "127.0.0.1" && host != "localhost" && host != "::1")
    log_warn("view: binding " + host + ": anyone who can reach this address can read the model and its photos");

  const fs::path model_dir = language_model_dir(out, method, "view");
  log_info("view: loading " + model_dir.string());
  if (scene.empty()) scene = run_scene_dir(out);
  ViewerModel model(model_dir, scene);
  ViewerServerOptions options;
  options.out = out;
  options.assets = assets;
  options.vendor = vendor;
  options.host = host;
  options.port = port;
  ViewerServer server(model, options);
  const int bound = server.bind();
  const std::string shown_host = host.find(':') != std::string::npos ? "[" + host + "]" : host;
  std::cout << "Viewer: http://" << shown_host << ":" << bound << "/" << std::endl;

  install_interrupt_handlers();
  // Ctrl-C / SIGTERM set a flag (core/interrupt.h); a watcher turns it into a clean stop.
  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done && !interrupt_requested()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    server.stop();
  });
  server.listen();
  done = true;
  watcher.join();
  log_info("view: stopped");
  return interrupt_requested() ? kInterruptedExit : 0;
}

}  // namespace cls
