// Where the coupler's SolverHub listens: a ZeroMQ endpoint given by the user (--endpoint) or a
// fresh ipc:// socket, checked and turned into the concrete addresses to bind. libzmq's bind takes
// an IP address or an interface name but no host name ("tcp://localhost:P": "No such device"),
// and IPv6 only with ZMQ_IPV6; this resolves host names itself and says when IPv6 is needed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace porosph::coupler {

/// An endpoint the hub cannot listen on: unknown transport, malformed address, unknown host,
/// address in use or not on this machine. The user's input when the user named it (exit 2).
struct BadEndpoint : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct BindPlan {
  /// Concrete endpoints to bind, in order: one for ipc:// and for an address, every address of a
  /// host name (so "localhost" listens on 127.0.0.1 and ::1 and nowhere else).
  std::vector<std::string> endpoints;
  bool ipv6 = false;      ///< some address is IPv6: set ZMQ_IPV6 before binding
  bool wildcard = false;  ///< tcp://*:P, 0.0.0.0 or [::]: every interface of the machine
  std::string ipc_path;   ///< the socket file of an ipc:// endpoint ("" for tcp, abstract sockets)
};

/// Checks `endpoint` ("ipc://PATH", "tcp://HOST:PORT" with HOST an IPv4 address, [IPv6], a host
/// name, an interface name or *, PORT a number or 0 / * for any free port) and resolves it.
/// Throws BadEndpoint.
BindPlan plan_bind(const std::string& endpoint);

/// The endpoint a solver on this machine connects to for a bound one: a wildcard address becomes
/// the loopback address of its family; anything else is returned unchanged.
std::string connectable(const std::string& bound_endpoint);

}  // namespace porosph::coupler
