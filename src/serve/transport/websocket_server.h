// The studio's network transport (docs/studio-protocol.md): one TCP port that serves plain
// HTTP GETs (the client's static files) and upgrades `/ws` to a WebSocket (RFC 6455).
// Built on websocketpp and standalone Asio from Debian. websocketpp 0.8 does not compile as
// C++20, so this header is plain C++17 with no websocketpp type in it and its one source
// file is compiled as C++17 (CMakeLists.txt, relight_websocket).
//
// Threads: run() turns the event loop on the calling thread; every handler is called there.
// send(), close_all() and stop() may be called from any thread (they are posted to the loop).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace relight {

using ConnectionId = std::uint64_t;

struct HttpResponse {
  int status = 200;
  std::string content_type = "text/plain; charset=utf-8";
  std::string body;
};

struct WebSocketHandlers {
  std::function<void(ConnectionId)> open;
  std::function<void(ConnectionId)> close;
  // A whole message; `binary` for binary frames, else UTF-8 text (validated by the transport).
  std::function<void(ConnectionId, const std::string& payload, bool binary)> message;
  // A plain HTTP request (method and resource path, query string removed).
  std::function<HttpResponse(const std::string& method, const std::string& path)> http;
};

struct WebSocketServerOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 8080;  // 0: any free port (see WebSocketServer::port())
  std::string websocket_path = "/ws";
  std::size_t max_message_bytes = std::size_t{1} << 20;  // larger: close code 1009
  bool stop_on_signals = true;                           // SIGINT, SIGTERM end run()
};

class WebSocketServer {
 public:
  // Binds and listens; throws std::runtime_error ("cannot listen on HOST:PORT: reason").
  WebSocketServer(const WebSocketServerOptions& options, WebSocketHandlers handlers);
  ~WebSocketServer();
  WebSocketServer(const WebSocketServer&) = delete;
  WebSocketServer& operator=(const WebSocketServer&) = delete;

  std::uint16_t port() const;
  // Runs the event loop until stop() (or a signal, when enabled).
  void run();
  void stop();
  // Queues a message to one connection; silently dropped when it has closed. A `droppable`
  // message (a frame, or a broadcast a newer one supersedes) is dropped too while the
  // connection still has more than kSlowClientBytes unsent: a client that does not read cannot
  // grow the queue. A connection with more than kStalledClientBytes unsent is closed (1008).
  static constexpr std::size_t kSlowClientBytes = std::size_t{8} << 20;
  static constexpr std::size_t kStalledClientBytes = std::size_t{64} << 20;
  void send(ConnectionId connection, std::string payload, bool binary, bool droppable = false);
  std::size_t connection_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace relight
