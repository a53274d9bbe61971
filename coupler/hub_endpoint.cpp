#include "coupler/hub_endpoint.h"

#include <arpa/inet.h>
#include <net/if.h>
#include <netdb.h>
#include <sys/socket.h>
#include <sys/un.h>

#include <algorithm>
#include <cstdlib>
#include <string_view>

namespace porosph::coupler {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

bool is_ipv4(const std::string& host) {
  in_addr address{};
  return ::inet_pton(AF_INET, host.c_str(), &address) == 1;
}

bool is_ipv6(const std::string& host) {
  in6_addr address{};
  return ::inet_pton(AF_INET6, host.c_str(), &address) == 1;
}

/// "0".."65535" or "*" (any free port, as libzmq's "*").
bool valid_port(const std::string& port) {
  if (port == "*") return true;
  if (port.empty() || port.size() > 5 ||
      !std::all_of(port.begin(), port.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return false;
  }
  return std::atoi(port.c_str()) <= 65535;
}

/// The IPv4 and IPv6 addresses of a host name, as getaddrinfo orders them, without repeats.
std::vector<std::string> addresses_of(const std::string& host, const std::string& endpoint) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int rc = ::getaddrinfo(host.c_str(), nullptr, &hints, &found);
  if (rc != 0) {
    throw BadEndpoint("cannot listen for solvers on '" + endpoint + "': unknown host '" + host +
                      "' (" + ::gai_strerror(rc) + ")");
  }
  std::vector<std::string> result;
  for (const addrinfo* a = found; a != nullptr; a = a->ai_next) {
    char text[INET6_ADDRSTRLEN] = {};
    const void* raw =
        a->ai_family == AF_INET6
            ? static_cast<const void*>(
                  &reinterpret_cast<const sockaddr_in6*>(a->ai_addr)->sin6_addr)
            : static_cast<const void*>(&reinterpret_cast<const sockaddr_in*>(a->ai_addr)->sin_addr);
    if ((a->ai_family != AF_INET && a->ai_family != AF_INET6) ||
        ::inet_ntop(a->ai_family, raw, text, sizeof text) == nullptr) {
      continue;
    }
    if (std::find(result.begin(), result.end(), text) == result.end()) result.emplace_back(text);
  }
  ::freeaddrinfo(found);
  if (result.empty()) {
    throw BadEndpoint("cannot listen for solvers on '" + endpoint + "': host '" + host +
                      "' has no IPv4 or IPv6 address");
  }
  return result;
}

BindPlan plan_ipc(const std::string& endpoint) {
  const std::string path = endpoint.substr(std::string_view("ipc://").size());
  if (path.empty() || path == "*") {
    throw BadEndpoint("cannot listen for solvers on '" + endpoint + "': ipc:// needs a path");
  }
  if (path.size() >= sizeof(sockaddr_un{}.sun_path)) {
    throw BadEndpoint("cannot listen for solvers on '" + endpoint + "': the path is longer than " +
                      std::to_string(sizeof(sockaddr_un{}.sun_path) - 1) + " characters");
  }
  BindPlan plan;
  plan.endpoints = {endpoint};
  if (path.front() != '@') plan.ipc_path = path;  // ipc://@name: an abstract socket, no file
  return plan;
}

BindPlan plan_tcp(const std::string& endpoint) {
  const std::string address = endpoint.substr(std::string_view("tcp://").size());
  const std::size_t colon = address.rfind(':');
  const auto bad = [&endpoint](const std::string& why) {
    return BadEndpoint("cannot listen for solvers on '" + endpoint + "': " + why);
  };
  if (colon == std::string::npos) throw bad("expected tcp://HOST:PORT");
  std::string host = address.substr(0, colon);
  const std::string port = address.substr(colon + 1);
  if (!valid_port(port)) throw bad("the port must be a number from 0 to 65535 (or *)");
  if (host.empty()) throw bad("expected tcp://HOST:PORT (HOST: an address, a host name or *)");
  if (host.find(';') != std::string::npos) throw bad("a source address (;) is not supported");
  BindPlan plan;
  if (host.front() == '[') {
    if (host.back() != ']' || !is_ipv6(host.substr(1, host.size() - 2))) {
      throw bad("'" + host + "' is not an IPv6 address in brackets");
    }
    plan.ipv6 = true;
    plan.wildcard = host == "[::]";
    plan.endpoints = {endpoint};
    return plan;
  }
  if (host == "*" || is_ipv4(host)) {
    plan.wildcard = host == "*" || host == "0.0.0.0";
    plan.endpoints = {endpoint};
    return plan;
  }
  if (is_ipv6(host)) throw bad("write an IPv6 address in brackets: tcp://[" + host + "]:" + port);
  if (::if_nametoindex(host.c_str()) != 0) {  // a network interface, e.g. eth0: libzmq binds it
    plan.endpoints = {endpoint};
    return plan;
  }
  for (const std::string& ip : addresses_of(host, endpoint)) {
    const bool v6 = ip.find(':') != std::string::npos;
    plan.ipv6 = plan.ipv6 || v6;
    plan.endpoints.push_back("tcp://" + (v6 ? "[" + ip + "]" : ip) + ":" + port);
  }
  return plan;
}

}  // namespace

BindPlan plan_bind(const std::string& endpoint) {
  if (starts_with(endpoint, "ipc://")) return plan_ipc(endpoint);
  if (starts_with(endpoint, "tcp://")) return plan_tcp(endpoint);
  throw BadEndpoint("cannot listen for solvers on '" + endpoint +
                    "': use ipc://PATH or tcp://HOST:PORT");
}

std::string connectable(const std::string& bound_endpoint) {
  for (const auto& [wildcard, loopback] :
       {std::pair<std::string_view, std::string_view>{"tcp://0.0.0.0:", "tcp://127.0.0.1:"},
        {"tcp://*:", "tcp://127.0.0.1:"},
        {"tcp://[::]:", "tcp://[::1]:"}}) {
    if (starts_with(bound_endpoint, wildcard)) {
      return std::string(loopback) + bound_endpoint.substr(wildcard.size());
    }
  }
  return bound_endpoint;
}

}  // namespace porosph::coupler
