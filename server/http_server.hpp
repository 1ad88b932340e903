// The HTTP server (http_beast.cpp, the only file that includes Boost.Beast/Asio): C++20
// coroutines on a few I/O threads, so thousands of idle keep-alive connections cost memory, not
// threads; handlers run on a separate pool because they may wait for the store.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

#include "server/http.hpp"

namespace frustum::server {

struct HttpLimits {
  std::size_t header_bytes = 8 * 1024;  // request line and headers (431 beyond)
  std::size_t body_bytes = 64 * 1024;   // request body (413 beyond)
  // Bodies of requests under this path may be larger: an author's whole problem set.
  std::string large_body_path = "/instructor/";
  std::size_t large_body_bytes = 2 * 1024 * 1024;
  int request_seconds = 10;             // to receive a request once it starts, and to answer it
  int idle_seconds = 60;                // a keep-alive connection with no request is closed
  std::size_t max_connections = 10000;  // further connections are closed at once
  std::size_t max_in_flight = 256;      // requests being handled; beyond, 429 with Retry-After
  int io_threads = 2;
  int handler_threads = 16;  // mostly waiting for a commit, which they share
};

struct HttpServerOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8080;  // 0: any free port (reported through on_listening)
  HttpLimits limits;
  std::function<void(unsigned short port)> on_listening;  // once accepting
  std::function<void(const std::string& line)> log;       // access log lines (no query, no body)
};

// Serves until SIGINT or SIGTERM, or until `stop` becomes true (checked a few times a second).
// Throws std::runtime_error when it cannot listen.
void run_http_server(const HttpServerOptions& options, const Handler& handler,
                     const std::atomic<bool>* stop = nullptr);

}  // namespace frustum::server
