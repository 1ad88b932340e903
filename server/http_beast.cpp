// Boost.Beast/Asio, kept to this one translation unit. Each connection is a coroutine: read a
// header within the idle (keep-alive) or request time, the body within the request time and
// the limits, hand the plain Request to the handler pool, write the Response, repeat.
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <memory>
#include <stdexcept>

#include "server/http_server.hpp"

namespace frustum::server {

namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
using asio::awaitable;
using asio::use_awaitable;
using tcp = asio::ip::tcp;

struct Shared {
  const HttpServerOptions& options;
  const Handler& handler;
  asio::thread_pool handlers;
  std::atomic<std::size_t> connections{0};
  std::atomic<std::size_t> in_flight{0};
};

Request to_request(const bhttp::request<bhttp::string_body>& r, const std::string& peer) {
  Request out;
  out.method = std::string(r.method_string());
  out.target = std::string(r.target());
  for (const auto& field : r) {
    std::string name(field.name_string());
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    out.headers.emplace_back(std::move(name), std::string(field.value()));
  }
  out.body = r.body();
  out.peer = peer;
  return out;
}

bhttp::response<bhttp::string_body> to_beast(const Response& r, unsigned version, bool keep) {
  bhttp::response<bhttp::string_body> out{static_cast<bhttp::status>(r.status), version};
  for (const auto& [name, value] : r.headers) out.insert(name, value);
  out.body() = r.body;
  out.keep_alive(keep);
  out.prepare_payload();
  return out;
}

Response plain(int status, const std::string& text) {
  Response r{status, {{"Content-Type", "text/plain; charset=utf-8"}}, text + "\n"};
  if (status == 503 || status == 429) r.set("Retry-After", "1");
  return r;
}

// Runs the handler on the pool (it may block on the store) and comes back to the connection.
awaitable<Response> handle(Shared& shared, Request request) {
  struct InFlight {
    std::atomic<std::size_t>& n;
    ~InFlight() { --n; }
  } in_flight{shared.in_flight};
  if (++shared.in_flight > shared.options.limits.max_in_flight)
    co_return plain(429, "busy: try again in a second");
  // A coroutine on the pool's executor: `co_await post(pool, use_awaitable)` would resume this
  // one on its own (the connection's I/O thread), and the handler would block that thread.
  co_return co_await asio::co_spawn(
      shared.handlers.get_executor(),
      [&]() -> awaitable<Response> {
        try {
          co_return shared.handler(request);
        } catch (const std::exception&) {
          co_return plain(500, "internal error");
        }
      },
      use_awaitable);
}

// The status for a request the parser refused.
int refusal(const beast::error_code& ec) {
  if (ec == bhttp::error::header_limit) return 431;
  if (ec == bhttp::error::body_limit) return 413;
  return 400;
}

void log_line(const Shared& shared, const Request& req, int status, double ms) {
  if (!shared.options.log) return;
  // The path only: tokens travel in queries and cookies, which are never logged.
  shared.options.log(req.method + " " + req.path() + " " + std::to_string(status) + " " +
                     std::to_string(static_cast<int>(ms)) + "ms");
}

awaitable<void> session(Shared& shared, tcp::socket socket) {
  struct Count {
    std::atomic<std::size_t>& n;
    ~Count() { --n; }
  } count{shared.connections};
  const HttpLimits& limits = shared.options.limits;
  beast::error_code ec;
  const std::string peer = socket.remote_endpoint(ec).address().to_string();
  beast::tcp_stream stream(std::move(socket));
  beast::flat_buffer buffer;
  for (;;) {
    bhttp::request_parser<bhttp::string_body> parser;
    parser.header_limit(static_cast<std::uint32_t>(limits.header_bytes));
    parser.body_limit(limits.body_bytes);
    stream.expires_after(std::chrono::seconds(limits.idle_seconds));
    co_await bhttp::async_read_header(stream, buffer, parser,
                                      asio::redirect_error(use_awaitable, ec));
    if (!ec) {
      const auto target = parser.get().target();
      if (!limits.large_body_path.empty() &&
          target.substr(0, limits.large_body_path.size()) == limits.large_body_path)
        parser.body_limit(limits.large_body_bytes);
      stream.expires_after(std::chrono::seconds(limits.request_seconds));
      co_await bhttp::async_read(stream, buffer, parser, asio::redirect_error(use_awaitable, ec));
    }
    if (ec == bhttp::error::end_of_stream || ec == beast::error::timeout ||
        ec == asio::error::eof || ec == asio::error::connection_reset)
      break;
    const auto started = std::chrono::steady_clock::now();
    Response response;
    Request request;
    bool keep = false;
    unsigned version = 11;
    if (ec) {
      response = plain(refusal(ec), status_reason(refusal(ec)));
    } else {
      request = to_request(parser.get(), peer);
      keep = parser.get().keep_alive();
      version = parser.get().version();
      response = co_await handle(shared, std::move(request));
    }
    log_line(shared, request, response.status,
             std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
                 .count());
    stream.expires_after(std::chrono::seconds(limits.request_seconds));
    auto out = to_beast(response, version, keep);
    co_await bhttp::async_write(stream, out, asio::redirect_error(use_awaitable, ec));
    if (ec || !keep) break;
  }
  stream.socket().shutdown(tcp::socket::shutdown_send, ec);
}

awaitable<void> listen(Shared& shared, tcp::acceptor& acceptor) {
  for (;;) {
    beast::error_code ec;
    tcp::socket socket = co_await acceptor.async_accept(asio::redirect_error(use_awaitable, ec));
    if (ec == asio::error::operation_aborted) co_return;
    if (ec) {
      // Out of file descriptors or a reset before accept: wait a moment rather than spin.
      asio::steady_timer pause(acceptor.get_executor(), std::chrono::milliseconds(50));
      co_await pause.async_wait(use_awaitable);
      continue;
    }
    if (shared.connections.load() >= shared.options.limits.max_connections) {
      socket.close(ec);
      continue;
    }
    ++shared.connections;
    asio::co_spawn(acceptor.get_executor(), session(shared, std::move(socket)), asio::detached);
  }
}

awaitable<void> watch_stop(const std::atomic<bool>* stop, asio::io_context& io) {
  asio::steady_timer timer(io);
  while (!stop->load()) {
    timer.expires_after(std::chrono::milliseconds(200));
    co_await timer.async_wait(use_awaitable);
  }
  io.stop();
}

}  // namespace

void run_http_server(const HttpServerOptions& options, const Handler& handler,
                     const std::atomic<bool>* stop) {
  const int io_threads = std::max(1, options.limits.io_threads);
  // The connections' coroutines, destroyed with `io`, count themselves out of `shared`.
  Shared shared{options, handler, asio::thread_pool(std::max(1, options.limits.handler_threads))};
  asio::io_context io(io_threads);
  tcp::acceptor acceptor(io);
  try {
    const tcp::endpoint at(asio::ip::make_address(options.host), options.port);
    acceptor.open(at.protocol());
    acceptor.set_option(asio::socket_base::reuse_address(true));
    acceptor.bind(at);
    acceptor.listen(asio::socket_base::max_listen_connections);
  } catch (const boost::system::system_error& e) {
    throw std::runtime_error("cannot listen on " + options.host + ":" +
                             std::to_string(options.port) + ": " + e.code().message());
  }
  if (options.on_listening) options.on_listening(acceptor.local_endpoint().port());
  asio::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](const beast::error_code&, int) { io.stop(); });
  asio::co_spawn(io, listen(shared, acceptor), asio::detached);
  if (stop) asio::co_spawn(io, watch_stop(stop, io), asio::detached);
  std::vector<std::thread> threads;
  for (int i = 1; i < io_threads; ++i) threads.emplace_back([&] { io.run(); });
  io.run();
  for (auto& t : threads) t.join();
  shared.handlers.join();
}

}  // namespace frustum::server
