#include "rt/live/live_server.hpp"

#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>

#include "rt/core/errors.hpp"

#ifdef RT_HAVE_HTTPLIB
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <httplib.h>
#include <thread>
#endif

namespace rt {

#ifdef RT_HAVE_HTTPLIB

bool live_view_built() {
    return true;
}

namespace {

// Why 127.0.0.1:port cannot be bound, in the system's words ("Address already in use").
std::string bind_problem(int port) {
    const int probe = socket(AF_INET, SOCK_STREAM, 0);
    if (probe < 0) return std::strerror(errno);
    const int yes = 1;
    setsockopt(probe, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);  // as the server does
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const bool bound = bind(probe, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
    const std::string problem = bound ? "the server could not listen" : std::strerror(errno);
    close(probe);
    return problem;
}

// How long a client may take, as nginx bounds it (client_header_timeout, keepalive_timeout): each read and
// each write of a connection at most kReadWriteSeconds, and a connection is closed once it has been idle for
// kIdleSeconds. A client slower than that is dropped; a page's requests take milliseconds.
constexpr time_t kReadWriteSeconds = 2;
constexpr time_t kIdleSeconds = 1;
// Connections served at once (cpp-httplib's default pool has 8 threads, which 8 slow clients fill).
constexpr int kMaxConnections = 64;

// Each connection on a thread of its own, up to kMaxConnections at once; another waits to be accepted.
class ConnectionThreads : public httplib::TaskQueue {
public:
    void enqueue(std::function<void()> serve) override {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [this] { return running_ < kMaxConnections; });
        ++running_;
        std::thread([this, serve = std::move(serve)] {
            serve();
            const std::lock_guard<std::mutex> done(mutex_);
            --running_;
            changed_.notify_all();
        }).detach();
    }
    // Waits for the connections still served (LiveServer::stop() has cut them short).
    void shutdown() override {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [this] { return running_ == 0; });
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    int running_ = 0;
};

// Shuts down every connection this process has accepted on 127.0.0.1:port, so that the thread serving it,
// waiting for a slow or idle client, returns at once: cpp-httplib keeps the sockets it accepts to itself,
// and its stop() closes only the one it listens on.
void shut_connections(int port) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd", ec)) {
        const int fd = std::atoi(entry.path().filename().c_str());
        sockaddr_in local{};
        socklen_t length = sizeof local;
        int listening = 0;
        socklen_t size = sizeof listening;
        if (getsockname(fd, reinterpret_cast<sockaddr*>(&local), &length) != 0 || local.sin_family != AF_INET ||
            ntohs(local.sin_port) != port)
            continue;
        if (getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &listening, &size) == 0 && listening != 0) continue;
        ::shutdown(fd, SHUT_RDWR);
    }
}

}  // namespace

struct LiveServer::Impl {
    struct Pending {
        LiveChange change;
        std::promise<std::optional<std::string>> answer;
    };

    httplib::Server server;
    std::thread listener;
    std::atomic<bool> listener_done = false;
    int port = 0;
    std::string page;

    std::mutex mutex;  // guards everything below
    std::condition_variable changed;
    std::optional<std::string> png;
    std::string state = "{}";
    std::deque<std::shared_ptr<Pending>> pending;
    bool stopping = false;

    // The Host a browser sends for this server, and the Origin of its own page.
    bool our_host(const std::string& host) const {
        const std::string p = ":" + std::to_string(port);
        return host == "127.0.0.1" + p || host == "localhost" + p;
    }

    void serve(const std::vector<LiveRoute>& routes) {
        configure_connections();
        refuse_other_hosts();
        add_routes(routes);
    }

    // One request a connection, bounded waits, a thread per connection.
    void configure_connections() {
        // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, with which a second server could share
        // a port already in use instead of being refused.
        server.set_socket_options([](socket_t socket) {
            const int yes = 1;
            setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
        });
        server.set_keep_alive_max_count(1);  // one request a connection
        server.set_keep_alive_timeout(kIdleSeconds);
        server.set_read_timeout(kReadWriteSeconds);
        server.set_write_timeout(kReadWriteSeconds);
        server.new_task_queue = [] { return new ConnectionThreads; };
    }

    // Before any route: one Host, ours, and no other page's Origin.
    void refuse_other_hosts() {
        server.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
            // One Host, as HTTP/1.1 requires (RFC 9112, 3.2): with two, which one a proxy or a browser
            // trusted is not known.
            if (request.get_header_value_count("Host") != 1) {
                response.status = 400;
                response.set_content("bad request: one Host header is required\n", "text/plain");
                return httplib::Server::HandlerResponse::Handled;
            }
            const std::string origin = request.get_header_value("Origin");
            if (!our_host(request.get_header_value("Host")) ||
                (!origin.empty() && !(origin.starts_with("http://") && our_host(origin.substr(7))))) {
                response.status = 403;
                response.set_content("refused: this server answers http://127.0.0.1:" + std::to_string(port) +
                                         "/ and http://localhost:" + std::to_string(port) + "/ only\n",
                                     "text/plain");
                return httplib::Server::HandlerResponse::Handled;
            }
            response.set_header("Cache-Control", "no-store");
            return httplib::Server::HandlerResponse::Unhandled;
        });
    }

    // The page, the routes a program adds, and the live view's state, image and changes.
    void add_routes(const std::vector<LiveRoute>& routes) {
        server.Get("/", [this](const httplib::Request&, httplib::Response& response) {
            response.set_content(page, "text/html; charset=utf-8");
        });
        for (const LiveRoute& route : routes) {
            server.Get(route.path, [answer = route.answer](const httplib::Request& request,
                                                           httplib::Response& response) {
                LiveQuery query;
                for (const auto& [name, value] : request.params) query.emplace(name, value);
                const LiveAnswer a = answer(query);
                response.status = a.status;
                response.set_content(a.body, a.content_type);
            });
        }
        server.Get("/state", [this](const httplib::Request&, httplib::Response& response) {
            const std::lock_guard<std::mutex> lock(mutex);
            response.set_content(state, "application/json");
        });
        server.Get("/image.png", [this](const httplib::Request&, httplib::Response& response) {
            const std::lock_guard<std::mutex> lock(mutex);
            if (!png) {
                response.status = 404;
                response.set_content("no pass has finished yet\n", "text/plain");
                return;
            }
            response.set_content(*png, "image/png");
        });
        server.Post("/change", [this](const httplib::Request& request, httplib::Response& response) {
            auto item = std::make_shared<Pending>();
            item->change = {request.get_param_value("kind"), request.get_param_value("name"),
                            request.get_param_value("value")};
            std::future<std::optional<std::string>> answer = item->answer.get_future();
            {
                const std::lock_guard<std::mutex> lock(mutex);
                if (stopping)
                    item->answer.set_value(std::string(kStopping));
                else
                    pending.push_back(item);
            }
            changed.notify_all();
            // The render answers at the end of its pass; a pass longer than this is answered "busy".
            if (answer.wait_for(std::chrono::seconds(60)) != std::future_status::ready) {
                response.status = 503;
                response.set_content("the render has not reached the end of its pass; try again\n", "text/plain");
                return;
            }
            std::optional<std::string> refusal;
            try {
                refusal = answer.get();
            } catch (const std::future_error&) {  // the run ended without answering
                refusal = std::string(kStopping);
            }
            response.status = refusal ? (*refusal == kStopping ? 503 : 400) : 200;
            response.set_content(refusal ? *refusal + "\n" : "ok\n", "text/plain");
        });
    }

    static constexpr const char* kStopping = "the live view is stopping";
};

LiveServer::LiveServer(int port, std::string page, std::vector<LiveRoute> routes)
    : impl_(std::make_unique<Impl>()) {
    impl_->page = std::move(page);
    impl_->serve(routes);
    // 127.0.0.1 only: no other machine can reach it.
    if (port == 0) {
        impl_->port = impl_->server.bind_to_any_port("127.0.0.1");
        if (impl_->port <= 0) throw InputError("--port 0: no free port on 127.0.0.1: " + bind_problem(0));
    } else {
        if (!impl_->server.bind_to_port("127.0.0.1", port))
            throw InputError("--port " + std::to_string(port) + ": cannot listen on 127.0.0.1:" +
                             std::to_string(port) + ": " + bind_problem(port));
        impl_->port = port;
    }
    impl_->listener = std::thread([this] {
        impl_->server.listen_after_bind();
        impl_->listener_done = true;
    });
    // stop() stops only a server that runs: wait until it does (or has failed).
    while (!impl_->server.is_running() && !impl_->listener_done)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

LiveServer::~LiveServer() {
    stop();
}

int LiveServer::port() const {
    return impl_->port;
}

void LiveServer::publish(std::optional<std::string> png, std::string state_json) {
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    if (png) impl_->png = std::move(png);
    impl_->state = std::move(state_json);
}

int LiveServer::answer_changes(const LiveChangeHandler& handler) {
    std::deque<std::shared_ptr<Impl::Pending>> waiting;
    {
        const std::lock_guard<std::mutex> lock(impl_->mutex);
        waiting.swap(impl_->pending);
    }
    int applied = 0;
    for (const auto& item : waiting) {
        const std::optional<std::string> refusal = handler(item->change);
        if (!refusal) ++applied;
        item->answer.set_value(refusal);
    }
    return applied;
}

void LiveServer::wait_for_change(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(impl_->mutex);
    impl_->changed.wait_for(lock, timeout, [&] { return !impl_->pending.empty(); });
}

void LiveServer::stop() {
    if (!impl_->listener.joinable()) return;
    {
        const std::lock_guard<std::mutex> lock(impl_->mutex);
        impl_->stopping = true;
        for (const auto& item : impl_->pending) item->answer.set_value(std::string(Impl::kStopping));
        impl_->pending.clear();
    }
    impl_->server.stop();
    // The listener ends once every connection's thread has: cut them short until it has (one accepted as
    // the server stopped included).
    while (!impl_->listener_done) {
        shut_connections(impl_->port);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    impl_->listener.join();
}

#else  // built without cpp-httplib

bool live_view_built() {
    return false;
}

struct LiveServer::Impl {};

LiveServer::LiveServer(int, std::string, std::vector<LiveRoute>) {
    throw InputError(
        "--live: this build has no live view: cpp-httplib was not found when it was configured (install "
        "libcpp-httplib-dev, then configure again)");
}
LiveServer::~LiveServer() = default;
int LiveServer::port() const {
    return 0;
}
void LiveServer::publish(std::optional<std::string>, std::string) {}
int LiveServer::answer_changes(const LiveChangeHandler&) {
    return 0;
}
void LiveServer::wait_for_change(std::chrono::milliseconds) {}
void LiveServer::stop() {}

#endif

}  // namespace rt
