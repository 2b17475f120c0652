// The web server's request handling: the real server (src/web) runs in this process on a
// loopback port, over a temporary home with one account signed in and one project. Each input
// is one raw HTTP exchange: its first byte says which headers the harness adds after the
// request line (1: the session cookie, 2: the CSRF token, 4: the right Host), the rest is
// written to a fresh connection as is (several pipelined requests are fine), then the write
// side is closed and the answer read. A 5xx answer, a server that does not answer and close
// within kAnswerTimeout, or a server that no longer accepts connections is a finding.
//
// Inputs that would start heavy work are skipped (a POST naming /runs or /designs other than
// /designs/stop: simulations and designs, which other tests cover), and so is a signed-in
// sign-out, which would end the harness' session.
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "app/accounts.hpp"
#include "app/home.hpp"
#include "finding.hpp"
#include "web/web_server.hpp"

namespace {

constexpr auto kAnswerTimeout = std::chrono::seconds(20);

struct Harness {
  std::unique_ptr<sd::web::WebServer> server;
  std::thread thread;
  int port = 0;
  std::string cookie, csrf;
};

// Never destroyed: the server's threads still run when the process exits.
Harness& harness() {
  static Harness* const h = new Harness;
  return *h;
}

void set_up() {
  Harness& h = harness();
  const auto home = std::filesystem::temp_directory_path() / ("sd-fuzz-http-" + std::to_string(::getpid()));
  std::filesystem::remove_all(home);
  std::filesystem::create_directories(home);
  {
    sd::app::Home h_home(home);
    sd::app::sign_up(h_home, "fuzz", "fuzz-password-1");
  }
  sd::web::WebServerOptions options;
  options.host = "127.0.0.1";
  options.port = 0;
  options.home = home;
  h.server = std::make_unique<sd::web::WebServer>(options);
  h.port = h.server->bind();
  h.thread = std::thread([&h] { h.server->serve(); });
  h.thread.detach();  // serves until the process ends

  httplib::Client client("127.0.0.1", h.port);
  client.set_read_timeout(std::chrono::seconds(60));
  const auto in = client.Post("/api/sign-in", R"({"name":"fuzz","password":"fuzz-password-1"})", "application/json");
  if (!in || in->status != 200) sd::fuzz::finding("the harness cannot sign in");
  const std::string set_cookie = in->get_header_value("Set-Cookie");
  h.cookie = set_cookie.substr(0, set_cookie.find(';'));
  h.csrf = nlohmann::json::parse(in->body).at("csrf").get<std::string>();
  const httplib::Headers headers{{"Cookie", h.cookie}, {"X-CSRF-Token", h.csrf}};
  // A project and saved software, so that the seeds' project routes reach real rows.
  const auto project = client.Post("/api/projects", headers, R"({"name":"p1","mission":"aac","budget":"2000"})",
                                   "application/json");
  const auto saved = client.Post("/api/projects/p1/software", headers,
                                 R"({"name":"s1","text":"--fsm-config --nstates 1 --s0 0 --rwm0 50"})",
                                 "application/json");
  if (!project || project->status != 200 || !saved || saved->status != 200)
    sd::fuzz::finding("the harness cannot make its project");
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// Lower case and percent-decoded, as the server will see the path.
std::string decoded(const std::string& raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '%' && i + 2 < raw.size() && hex_value(raw[i + 1]) >= 0 && hex_value(raw[i + 2]) >= 0) {
      out += static_cast<char>(hex_value(raw[i + 1]) * 16 + hex_value(raw[i + 2]));
      i += 2;
    } else {
      out += raw[i];
    }
  }
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool skipped(const std::string& raw, bool signed_in) {
  const std::string text = decoded(raw);
  if (signed_in && text.find("sign-out") != std::string::npos) return true;
  if (text.find("post") == std::string::npos) return false;
  if (text.find("/runs") != std::string::npos) return true;
  for (auto at = text.find("/designs"); at != std::string::npos; at = text.find("/designs", at + 1))
    if (text.compare(at, 13, "/designs/stop") != 0) return true;
  return false;
}

// The request with the harness' headers put after its first line.
std::string request_of(const std::string& raw, std::uint8_t flags) {
  const Harness& h = harness();
  std::string headers;
  if (flags & 1) headers += "Cookie: " + h.cookie + "\r\n";
  if (flags & 2) headers += "X-CSRF-Token: " + h.csrf + "\r\n";
  if (flags & 4) headers += "Host: 127.0.0.1:" + std::to_string(h.port) + "\r\n";
  const auto line_end = raw.find('\n');
  if (headers.empty() || line_end == std::string::npos) return raw;
  return raw.substr(0, line_end + 1) + headers + raw.substr(line_end + 1);
}

// "ESTABLISHED, 0 segments unacknowledged": how the connection stands, for a finding's message.
std::string connection_state(int fd) {
  tcp_info info{};
  socklen_t size = sizeof info;
  if (::getsockopt(fd, IPPROTO_TCP, TCP_INFO, &info, &size) != 0) return "unknown";
  static const char* const kStates[] = {"?",          "ESTABLISHED", "SYN_SENT", "SYN_RECV",  "FIN_WAIT1", "FIN_WAIT2",
                                        "TIME_WAIT",  "CLOSE",       "CLOSE_WAIT", "LAST_ACK", "LISTEN",   "CLOSING"};
  const char* state = info.tcpi_state < std::size(kStates) ? kStates[info.tcpi_state] : "?";
  return std::string(state) + ", " + std::to_string(info.tcpi_unacked) + " segments unacknowledged, " +
         std::to_string(info.tcpi_retransmits) + " retransmissions";
}

// Waits until `fd` is ready for `events` or `deadline` passes; false on the deadline. A signal
// is no answer: libFuzzer's -timeout is a SIGALRM every half timeout, and when it landed on
// this thread (one of the server's 515) poll and connect returned EINTR, which the first long
// runs reported as a server that "accepts no connection" or "neither answered nor closed".
bool wait_for(int fd, short events, std::chrono::steady_clock::time_point deadline) {
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, events, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready > 0) return true;
    if (ready < 0 && errno != EINTR) return false;
  }
}

void connect_to_server(int fd, std::chrono::steady_clock::time_point deadline) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(harness().port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) return;
  int error = errno;
  if (error == EINTR) {  // the handshake goes on: wait for it and ask how it ended
    socklen_t size = sizeof error;
    error = wait_for(fd, POLLOUT, deadline) && ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size) == 0 ? error : ETIMEDOUT;
    if (error == 0) return;
  }
  sd::fuzz::finding(std::string("the server accepts no connection: ") + std::strerror(error));
}

// Everything the server answers until it closes the connection.
std::string exchange(const std::string& request) {
  const auto deadline = std::chrono::steady_clock::now() + kAnswerTimeout;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) sd::fuzz::finding(std::string("the harness has no socket: ") + std::strerror(errno));
  connect_to_server(fd, deadline);
  for (std::size_t sent = 0; sent < request.size();) {
    const ssize_t n = ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the server may close early on a malformed request
    sent += static_cast<std::size_t>(n);
  }
  ::shutdown(fd, SHUT_WR);
  std::string answer;
  char buffer[16384];
  for (;;) {
    if (!wait_for(fd, POLLIN, deadline))
      sd::fuzz::finding("the server neither answered nor closed the connection within 20 s (" + connection_state(fd) +
                        ", " + std::to_string(answer.size()) + " bytes answered)");
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return answer;
}

// A status line of 5xx at the start of the answer or of a later answer on the connection.
bool server_error(const std::string& answer) {
  for (std::size_t at = 0; at != std::string::npos; at = answer.find("\r\nHTTP/1.", at + 1)) {
    const std::size_t status = answer.find(' ', at);
    if (status != std::string::npos && status + 1 < answer.size() && status < at + 12 && answer[status + 1] == '5')
      return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  set_up();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const std::string raw(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (skipped(raw, data[0] & 1)) return -1;
  const std::string answer = exchange(request_of(raw, data[0]));
  if (server_error(answer)) sd::fuzz::finding("5xx answer: " + answer.substr(0, answer.find("\r\n\r\n")));
  return 0;
}
