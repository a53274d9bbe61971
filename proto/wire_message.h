// One serialised Protobuf message as one ZeroMQ frame, written straight into the frame's buffer
// (no intermediate string: one copy of the payload less per message than serialising into a
// buffer that zmq_send then copies).
#pragma once

#include <google/protobuf/message_lite.h>

#include <cstdint>
#include <zmq.hpp>

namespace porosph::wire {

inline zmq::message_t to_frame(const google::protobuf::MessageLite& message) {
  zmq::message_t frame(message.ByteSizeLong());
  message.SerializeWithCachedSizesToArray(static_cast<std::uint8_t*>(frame.data()));
  return frame;
}

}  // namespace porosph::wire
