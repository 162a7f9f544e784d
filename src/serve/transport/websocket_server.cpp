// websocketpp + standalone Asio behind serve/transport/websocket_server.h (C++17: see there).
// One asio server endpoint: HTTP requests go to the `http` handler, upgrades are accepted on
// the WebSocket path only, and whole messages go to the `message` handler. websocketpp
// enforces RFC 6455 itself: invalid UTF-8 in a text message closes with 1007, a message over
// max_message_bytes with 1009.
#define ASIO_STANDALONE
#include "serve/transport/websocket_server.h"

#include <atomic>
#include <csignal>
#include <iostream>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

namespace relight {

namespace {

using Endpoint = websocketpp::server<websocketpp::config::asio>;
using Handle = websocketpp::connection_hdl;

std::string path_of(const std::string& resource) {
  const std::size_t q = resource.find_first_of("?#");
  return q == std::string::npos ? resource : resource.substr(0, q);
}

}  // namespace

struct WebSocketServer::Impl {
  WebSocketServerOptions options;
  WebSocketHandlers handlers;
  Endpoint endpoint;
  std::unique_ptr<asio::signal_set> signals;
  // Loop thread only.
  std::map<Handle, ConnectionId, std::owner_less<Handle>> ids;
  std::map<ConnectionId, Handle> handles;
  ConnectionId next_id = 1;
  std::atomic<std::size_t> open_count{0};
  std::atomic<bool> stopping{false};

  void close_everything() {
    asio::error_code ec;
    endpoint.stop_listening(ec);
    for (auto& [id, handle] : handles) {
      websocketpp::lib::error_code close_ec;
      endpoint.close(handle, websocketpp::close::status::going_away, "server stopping", close_ec);
    }
    if (signals) signals->cancel(ec);
  }
};

WebSocketServer::WebSocketServer(const WebSocketServerOptions& options, WebSocketHandlers handlers)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.options = options;
  s.handlers = std::move(handlers);
  Endpoint& e = s.endpoint;
  e.clear_access_channels(websocketpp::log::alevel::all);
  e.clear_error_channels(websocketpp::log::elevel::all);
  e.set_error_channels(websocketpp::log::elevel::fatal);
  e.init_asio();
  e.set_reuse_addr(true);
  e.set_max_message_size(options.max_message_bytes);
  e.set_max_http_body_size(std::size_t{64} * 1024);

  // Frames go out at once: without TCP_NODELAY, Nagle's algorithm holds a frame's last segment
  // until the client's delayed ACK (up to 40 ms on Linux), measured as ~100 ms of latency.
  e.set_socket_init_handler([](const Handle&, asio::ip::tcp::socket& socket) {
    asio::error_code ec;
    socket.set_option(asio::ip::tcp::no_delay(true), ec);
  });
  // Browsers let any page open a WebSocket to any address, so an upgrade that carries an
  // Origin (every browser's does) must come from a page this server served: the Origin's
  // host:port equals the Host the browser asked for. Clients without one (scripts) pass.
  e.set_validate_handler([&s](const Handle& h) {
    const Endpoint::connection_ptr c = s.endpoint.get_con_from_hdl(h);
    if (path_of(c->get_resource()) != s.options.websocket_path) return false;
    const std::string origin = c->get_request_header("Origin");
    if (origin.empty()) return true;
    const std::size_t scheme = origin.find("://");
    return scheme != std::string::npos &&
           origin.substr(scheme + 3) == c->get_request_header("Host");
  });
  e.set_open_handler([&s](const Handle& h) {
    const ConnectionId id = s.next_id++;
    s.ids[h] = id;
    s.handles[id] = h;
    ++s.open_count;
    try {
      if (s.handlers.open) s.handlers.open(id);
    } catch (const std::exception& e) {
      std::cerr << "relight serve: internal error on a new connection: " << e.what() << std::endl;
      websocketpp::lib::error_code ec;
      s.endpoint.close(h, websocketpp::close::status::internal_endpoint_error, "internal error",
                       ec);
    }
  });
  e.set_close_handler([&s](const Handle& h) {
    const auto it = s.ids.find(h);
    if (it == s.ids.end()) return;
    const ConnectionId id = it->second;
    s.handles.erase(id);
    s.ids.erase(it);
    --s.open_count;
    try {
      if (s.handlers.close) s.handlers.close(id);
    } catch (const std::exception& e) {
      std::cerr << "relight serve: internal error on a closed connection: " << e.what()
                << std::endl;
    }
  });
  e.set_message_handler([&s](const Handle& h, const Endpoint::message_ptr& m) {
    const auto it = s.ids.find(h);
    if (it == s.ids.end() || !s.handlers.message) return;
    try {  // a handler's failure must not end the event loop (and every other connection)
      s.handlers.message(it->second, m->get_payload(),
                         m->get_opcode() == websocketpp::frame::opcode::binary);
    } catch (const std::exception& e) {
      std::cerr << "relight serve: internal error on a message: " << e.what() << std::endl;
    }
  });
  e.set_http_handler([&s](const Handle& h) {
    const Endpoint::connection_ptr c = s.endpoint.get_con_from_hdl(h);
    HttpResponse r{404, "text/plain; charset=utf-8", "not found\n"};
    try {
      if (s.handlers.http)
        r = s.handlers.http(c->get_request().get_method(), path_of(c->get_resource()));
    } catch (const std::exception& e) {
      r = {500, "text/plain; charset=utf-8", std::string("internal error: ") + e.what() + "\n"};
    }
    c->set_status(static_cast<websocketpp::http::status_code::value>(r.status));
    c->replace_header("Content-Type", r.content_type);
    c->replace_header("Cache-Control", "no-store");
    c->set_body(r.body);
  });

  asio::error_code ec;
  const asio::ip::address address = asio::ip::make_address(options.host, ec);
  const std::string where = options.host + ":" + std::to_string(options.port);
  if (ec) throw std::runtime_error("cannot listen on " + where + ": not an IP address");
  e.listen(asio::ip::tcp::endpoint(address, options.port), ec);
  if (ec) throw std::runtime_error("cannot listen on " + where + ": " + ec.message());
  e.start_accept(ec);
  if (ec) throw std::runtime_error("cannot listen on " + where + ": " + ec.message());
}

WebSocketServer::~WebSocketServer() {
  try {
    if (impl_->endpoint.is_listening()) {
      asio::error_code ec;
      impl_->endpoint.stop_listening(ec);
    }
  } catch (...) {  // nothing to report from a destructor; the socket closes with the process
  }
}

std::uint16_t WebSocketServer::port() const {
  asio::error_code ec;
  const asio::ip::tcp::endpoint local = impl_->endpoint.get_local_endpoint(ec);
  return ec ? impl_->options.port : local.port();
}

void WebSocketServer::run() {
  Impl& s = *impl_;
  if (s.options.stop_on_signals) {
    s.signals = std::make_unique<asio::signal_set>(s.endpoint.get_io_service(), SIGINT, SIGTERM);
    s.signals->async_wait([&s](const asio::error_code& ec, int) {
      if (!ec) s.close_everything();
    });
  }
  s.endpoint.run();
}

void WebSocketServer::stop() {
  Impl& s = *impl_;
  if (s.stopping.exchange(true)) return;
  s.endpoint.get_io_service().post([&s] { s.close_everything(); });
}

void WebSocketServer::send(ConnectionId connection, std::string payload, bool binary,
                           bool droppable) {
  Impl& s = *impl_;
  s.endpoint.get_io_service().post([&s, connection, binary, droppable, p = std::move(payload)] {
    const auto it = s.handles.find(connection);
    if (it == s.handles.end()) return;
    websocketpp::lib::error_code ec;  // a connection closing meanwhile: dropped
    const Endpoint::connection_ptr c = s.endpoint.get_con_from_hdl(it->second, ec);
    if (ec) return;
    const std::size_t buffered = c->get_buffered_amount();
    if (droppable && buffered > kSlowClientBytes) return;
    if (buffered > kStalledClientBytes) {  // it does not read at all: let it go
      c->close(websocketpp::close::status::policy_violation, "client does not read", ec);
      return;
    }
    s.endpoint.send(it->second, p.data(), p.size(),
                    binary ? websocketpp::frame::opcode::binary : websocketpp::frame::opcode::text,
                    ec);
  });
}

std::size_t WebSocketServer::connection_count() const {
  return impl_->open_count.load();
}

}  // namespace relight
