#include "viewer/viewer_server.h"

#include <httplib.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "core/log.h"
#include "viewer/static_files.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void send_error(httplib::Response& res, int status, const std::string& what) {
  res.status = status;
  res.set_content(json{{"error", what}}.dump(), "application/json");
}

void send_file(httplib::Response& res, const fs::path& root, const std::string& relative) {
  const auto file = file_under(root, relative);
  if (!file) return send_error(res, 404, "not found");
  std::ifstream in(*file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) return send_error(res, 500, "cannot read the file");
  res.set_content(bytes.str(), content_type_of(*file).c_str());
}

ViewerQuery query_of(const httplib::Request& req) {
  ViewerQuery q;
  q.text = req.get_param_value("q");
  if (req.has_param("level")) q.level = req.get_param_value("level");
  if (req.has_param("mode")) q.mode = req.get_param_value("mode");
  try {
    if (req.has_param("threshold")) q.threshold = std::stod(req.get_param_value("threshold"));
    if (req.has_param("top")) q.top = std::stoul(req.get_param_value("top"));
  } catch (const std::exception&) {
    throw UsageError("threshold and top must be numbers");
  }
  return q;
}

}  // namespace

struct ViewerServer::Impl {
  ViewerModel& model;
  ViewerServerOptions options;
  httplib::Server server;
  // listen() and stop() from different threads (ViewerServer::stop)
  std::atomic<bool> stop_requested{false}, listening{false}, listen_returned{false};

  // Runs a handler; a bad request becomes 400 with its reason, anything else 500, and the server goes on.
  template <class F>
  static void guarded(httplib::Response& res, F&& handler) {
    try {
      handler();
    } catch (const UsageError& e) {
      send_error(res, 400, e.what());
    } catch (const std::exception& e) {
      log_warn(std::string("view: ") + e.what());
      send_error(res, 500, e.what());
    }
  }

  Impl(ViewerModel& m, ViewerServerOptions o) : model(m), options(std::move(o)) {
    server.set_payload_max_length(options.max_request_bytes);
    server.set_read_timeout(5, 0);
    server.set_write_timeout(30, 0);
    server.Get("/", [this](const httplib::Request&, httplib::Response& res) {
      send_file(res, options.assets, "index.html");
    });
    server.Get(R"(/app/(.+))", [this](const httplib::Request& req, httplib::Response& res) {
      send_file(res, options.assets, req.matches[1]);
    });
    server.Get(R"(/vendor/(.+))", [this](const httplib::Request& req, httplib::Response& res) {
      send_file(res, options.vendor, req.matches[1]);
    });
    server.Get(R"(/files/(.+))", [this](const httplib::Request& req, httplib::Response& res) {
      send_file(res, options.out, req.matches[1]);
    });
    server.Get("/api/model", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(model.model_json().dump(), "application/json");
    });
    server.Get("/api/gaussians", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(model.gaussians_buffer(), "application/octet-stream");
    });
    server.Get("/api/citymesh", [this](const httplib::Request&, httplib::Response& res) {
      if (model.city_mesh_buffer().empty()) return send_error(res, 404, "no city mesh beside the model's label maps");
      res.set_content(model.city_mesh_buffer(), "application/octet-stream");
    });
    server.Get("/api/changes", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(model.changes_json().dump(), "application/json");
    });
    server.Get("/api/objects", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(model.objects_json().dump(), "application/json");
    });
    server.Get(R"(/api/image/(\d{1,9}))", [this](const httplib::Request& req, httplib::Response& res) {
      const std::string path = model.image_path(std::stoul(req.matches[1]));
      if (path.empty()) return send_error(res, 404, "no such view");
      send_file(res, fs::path(path).parent_path(), fs::path(path).filename().string());
    });
    server.Get("/api/query", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] { res.set_content(model.answer(query_of(req)).info.dump(), "application/json"); });
    });
    server.Get("/api/scores", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        const at::Tensor s = model.answer(query_of(req)).scores;
        res.set_content(std::string(static_cast<const char*>(s.data_ptr()), s.numel() * sizeof(float)),
                        "application/octet-stream");
      });
    });
    server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) send_error(res, res.status, res.status == 404 ? "not found" : "bad request");
    });
    server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
      send_error(res, 500, "internal error");
    });
  }
};

ViewerServer::ViewerServer(ViewerModel& model, ViewerServerOptions options)
    : impl_(std::make_unique<Impl>(model, std::move(options))) {}

ViewerServer::~ViewerServer() = default;

int ViewerServer::bind() {
  const ViewerServerOptions& o = impl_->options;
  if (o.port == 0) {
    const int port = impl_->server.bind_to_any_port(o.host);
    if (port <= 0) throw Error("view: cannot bind " + o.host + " (any port)");
    return port;
  }
  if (!impl_->server.bind_to_port(o.host, o.port))
    throw Error(cat("view: cannot bind ", o.host, ":", o.port, " (in use? pass --port 0 for any free port)"));
  return o.port;
}

void ViewerServer::listen() {
  Impl& i = *impl_;
  i.listening = true;
  if (!i.stop_requested) i.server.listen_after_bind();
  i.listen_returned = true;
}

// httplib's stop() does nothing until listen_after_bind() has marked the server running, and the listener
// then blocks in accept() for good: a stop that came between listen()'s start and that point was lost (a
// test that stopped its server at once hung at exit). listen() marks itself before it looks at the request,
// and stop() requests before it looks at listen(), so one of the two sees the other: either listen() returns
// without serving, or stop() waits until the server runs (or listen() has returned) and then stops it.
void ViewerServer::stop() {
  Impl& i = *impl_;
  i.stop_requested = true;
  if (!i.listening) return;
  while (!i.server.is_running() && !i.listen_returned) std::this_thread::yield();
  i.server.stop();
}

}  // namespace cls
