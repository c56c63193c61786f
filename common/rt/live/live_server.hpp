// The live view's web server (live_view.hpp): http://127.0.0.1:PORT serves the page, the image of the last
// pass and the run's state, and takes the page's changes of knobs and effects. Bound to the loopback
// address only; a request whose Host is not 127.0.0.1:PORT or localhost:PORT (DNS rebinding), or whose
// Origin is another site's, is refused with 403. Built with cpp-httplib (Debian libcpp-httplib-dev); a build
// without it has no live view, and a server then refuses to start.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rt {

inline constexpr int kDefaultLivePort = 8765;

// Whether this build has the live view (cpp-httplib was found when it was configured).
bool live_view_built();

// A change the page asks for: a knob (`kind` "knob", `name` "--sampling", `value` "light") or an effect
// (`kind` "effect", `name` "shadows", `value` "on" or "off").
struct LiveChange {
    std::string kind;
    std::string name;
    std::string value;
};
// Applies a change, or refuses it: returns the message saying why (the page shows it; HTTP 400).
using LiveChangeHandler = std::function<std::optional<std::string>(const LiveChange&)>;

// A GET path the server answers besides its own (the sampler view's /samplers and /sample): the answer is
// computed from the request's query parameters (the first value of each name) on the serving thread.
struct LiveAnswer {
    int status = 200;
    std::string body;
    std::string content_type = "application/json";
};
using LiveQuery = std::map<std::string, std::string>;
struct LiveRoute {
    std::string path;
    std::function<LiveAnswer(const LiveQuery&)> answer;
};

class LiveServer {
public:
    // Binds 127.0.0.1:port (0: a free port, port() says which) and serves `page` and `routes`. Throws
    // InputError naming --port when the port cannot be had (in use, or reserved), or --live when this build
    // has no live view.
    LiveServer(int port, std::string page, std::vector<LiveRoute> routes = {});
    ~LiveServer();  // stop()
    LiveServer(const LiveServer&) = delete;
    LiveServer& operator=(const LiveServer&) = delete;

    int port() const;
    // What the page fetches: the picture of the last pass (PNG bytes), and the state as JSON.
    void publish(std::optional<std::string> png, std::string state_json);
    // Answers, on the calling thread, every change the page has asked for since; returns how many were
    // applied (the others are refused with the handler's message).
    int answer_changes(const LiveChangeHandler& handler);
    // Waits until the page asks for a change, or `timeout` passes.
    void wait_for_change(std::chrono::milliseconds timeout);
    // Refuses the changes still waiting (503) and stops serving.
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rt
