#pragma once
// `citylangsplat view`: a local web server (cpp-httplib) for a trained model: the page of web/viewer,
// its npm renderer, and a JSON/binary API answered by a ViewerModel (docs/viewer.md lists the API).
// Binds 127.0.0.1 unless told otherwise; serves files only under its asset folders and OUT.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "viewer/viewer_model.h"

namespace cls {

struct ViewerServerOptions {
  std::filesystem::path out;         // what `files/` serves: the run or model directory
  std::filesystem::path assets;      // web/viewer (index.html, viewer.js ...)
  std::filesystem::path vendor;      // npm's node_modules (three, the splat renderer)
  std::string host = "127.0.0.1";
  int port = 8080;                   // 0 = any free port
  size_t max_request_bytes = 16 * 1024;
};

class ViewerServer {
 public:
  ViewerServer(ViewerModel& model, ViewerServerOptions options);
  ~ViewerServer();

  // Binds the socket; returns the port (the chosen one for port 0). cls::Error when it cannot bind.
  int bind();
  // Serves until stop() (from any thread, before or after listen() has begun: a stop that comes first
  // makes listen() return at once).
  void listen();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cls
