#include "proto/wire_frames.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

#include "proto/wire_convert.h"
#include "proto/wire_field_codec.h"

namespace porosph::wire {
using namespace field;  // the wire primitives of wire_field_codec.h

std::size_t StateFrame::prepare(const coupling::StepState& state,
                                const coupling::StateDelta& delta) {
  state_ = &state;
  delta_ = delta;
  sent_ = coupling::SentParticles(state, delta);
  const std::size_t n = state.overlap_id.size();
  id_bytes_ = delta.same_set ? 0 : varint_data_bytes(state.overlap_id);
  material_bytes_ = delta.same_set ? 0 : varint_data_bytes(state.overlap_material);
  to_wire(state.diagnostics, diagnostics_);
  diagnostics_bytes_ = diagnostics_.ByteSizeLong();
  const auto per_step = [&](const std::vector<double>& v, std::size_t per_particle) {
    return sent_.count(v, per_particle);
  };
  const std::size_t set_count = delta.same_set ? 0 : n;
  body_bytes_ = varint_field_bytes(1, state.step) + double_field_bytes(2, state.time) +
                double_field_bytes(3, state.dt_limit) + double_field_bytes(4, state.dt_cfl) +
                double_field_bytes(5, state.dt_viscous) + double_field_bytes(6, state.dt_force) +
                packed_varints_bytes(7, set_count, id_bytes_) +
                packed_doubles_bytes(8, per_step(state.overlap_position, sent_.dimension)) +
                packed_doubles_bytes(9, per_step(state.overlap_velocity, sent_.dimension)) +
                packed_doubles_bytes(10, per_step(state.overlap_density, 1)) +
                packed_doubles_bytes(11, delta.same_set ? 0 : state.overlap_mass.size()) +
                packed_doubles_bytes(12, per_step(state.overlap_porosity, 1)) +
                packed_varints_bytes(13, delta.same_set ? 0 : state.overlap_material.size(),
                                     material_bytes_) +
                delimited_bytes(14, diagnostics_bytes_) +
                packed_doubles_bytes(15, state.region_min.size()) +
                packed_doubles_bytes(16, state.region_max.size()) +
                varint_field_bytes(17, state.checkpoint_written) +
                varint_field_bytes(18, delta.same_set ? 1 : 0) +
                varint_field_bytes(19, delta.unchanged_tail) +
                packed_doubles_bytes(20, per_step(state.overlap_update_base, sent_.dimension)) +
                packed_doubles_bytes(21, per_step(state.overlap_update_rate, sent_.dimension));
  return delimited_bytes(Envelope::kStateFieldNumber, body_bytes_);
}

void StateFrame::write(std::uint8_t* p) const {
  const coupling::StepState& s = *state_;
  const auto per_step = [&](int field, const std::vector<double>& v, std::size_t per_particle,
                            std::uint8_t* at) {
    return write_packed_doubles(field, v.data(), sent_.count(v, per_particle), at);
  };
  p = write_length(Envelope::kStateFieldNumber, body_bytes_, p);
  p = write_varint_field(1, s.step, p);
  p = write_double_field(2, s.time, p);
  p = write_double_field(3, s.dt_limit, p);
  p = write_double_field(4, s.dt_cfl, p);
  p = write_double_field(5, s.dt_viscous, p);
  p = write_double_field(6, s.dt_force, p);
  if (!delta_.same_set) p = write_packed_varints(7, s.overlap_id, id_bytes_, p);
  p = per_step(8, s.overlap_position, sent_.dimension, p);
  p = per_step(9, s.overlap_velocity, sent_.dimension, p);
  p = per_step(10, s.overlap_density, 1, p);
  if (!delta_.same_set) {
    p = write_packed_doubles(11, s.overlap_mass.data(), s.overlap_mass.size(), p);
  }
  p = per_step(12, s.overlap_porosity, 1, p);
  if (!delta_.same_set) p = write_packed_varints(13, s.overlap_material, material_bytes_, p);
  p = write_length(14, diagnostics_bytes_, p);
  p = diagnostics_.SerializeWithCachedSizesToArray(p);
  p = write_packed_doubles(15, s.region_min.data(), s.region_min.size(), p);
  p = write_packed_doubles(16, s.region_max.data(), s.region_max.size(), p);
  p = write_varint_field(17, s.checkpoint_written, p);
  p = write_varint_field(18, delta_.same_set ? 1 : 0, p);
  p = write_varint_field(19, delta_.unchanged_tail, p);
  p = per_step(20, s.overlap_update_base, sent_.dimension, p);
  per_step(21, s.overlap_update_rate, sent_.dimension, p);
}

std::size_t CommandFrame::prepare(const coupling::StepCommand& c) {
  command_ = &c;
  body_bytes_ = varint_field_bytes(1, c.step) + double_field_bytes(2, c.time) +
                double_field_bytes(3, c.dt) + varint_field_bytes(4, c.write_output ? 1 : 0) +
                varint_field_bytes(5, c.output_index) + varint_field_bytes(6, c.stop ? 1 : 0) +
                packed_doubles_bytes(7, c.interaction_acceleration.size()) +
                packed_doubles_bytes(8, c.saturation.size()) +
                packed_doubles_bytes(9, c.other_region_min.size()) +
                packed_doubles_bytes(10, c.other_region_max.size()) +
                varint_field_bytes(11, c.write_checkpoint ? 1 : 0) +
                varint_field_bytes(12, c.checkpoint_index) +
                packed_doubles_bytes(13, c.interaction_rate.size()) +
                packed_doubles_bytes(14, c.porosity.size()) +
                packed_doubles_bytes(15, c.wall_speed.size()) +
                packed_doubles_bytes(16, c.load_force.size());
  return delimited_bytes(Envelope::kCommandFieldNumber, body_bytes_);
}

void CommandFrame::write(std::uint8_t* p) const {
  const coupling::StepCommand& c = *command_;
  const auto doubles = [](int field, const std::vector<double>& v, std::uint8_t* at) {
    return write_packed_doubles(field, v.data(), v.size(), at);
  };
  p = write_length(Envelope::kCommandFieldNumber, body_bytes_, p);
  p = write_varint_field(1, c.step, p);
  p = write_double_field(2, c.time, p);
  p = write_double_field(3, c.dt, p);
  p = write_varint_field(4, c.write_output ? 1 : 0, p);
  p = write_varint_field(5, c.output_index, p);
  p = write_varint_field(6, c.stop ? 1 : 0, p);
  p = doubles(7, c.interaction_acceleration, p);
  p = doubles(8, c.saturation, p);
  p = doubles(9, c.other_region_min, p);
  p = doubles(10, c.other_region_max, p);
  p = write_varint_field(11, c.write_checkpoint ? 1 : 0, p);
  p = write_varint_field(12, c.checkpoint_index, p);
  p = doubles(13, c.interaction_rate, p);
  p = doubles(14, c.porosity, p);
  p = doubles(15, c.wall_speed, p);
  doubles(16, c.load_force, p);
}

bool envelope_body(const void* data, std::size_t size, int field, const std::uint8_t** body,
                   std::size_t* body_size) {
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  CodedInputStream in(bytes, static_cast<int>(size));
  const std::uint32_t tag = in.ReadTag();
  std::uint32_t length = 0;
  if (tag != WireFormatLite::MakeTag(field, kDelimited) || !in.ReadVarint32(&length) ||
      static_cast<std::size_t>(in.CurrentPosition()) + length != size) {
    return false;
  }
  *body = bytes + in.CurrentPosition();
  *body_size = length;
  return true;
}

bool read_state_body(const std::uint8_t* data, std::size_t size, coupling::StepState& out,
                     Diagnostics& scratch) {
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  CodedInputStream in(data, static_cast<int>(size));
  in.PushLimit(static_cast<int>(size));  // bytes_left() measures against it
  out.step = 0;
  out.time = out.dt_limit = out.dt_cfl = out.dt_viscous = out.dt_force = 0.0;
  out.clear_overlap();
  out.region_min.clear();
  out.region_max.clear();
  out.checkpoint_written = 0;
  out.delta = coupling::StateDelta{};
  bool diagnostics_read = false;
  for (;;) {
    const std::uint32_t tag = in.ReadTag();
    if (tag == 0) break;
    const WireType type = WireFormatLite::GetTagWireType(tag);
    std::uint64_t v = 0;
    bool ok = true;
    switch (WireFormatLite::GetTagFieldNumber(tag)) {
      case 1:
        ok = read_varint(in, type, v);
        out.step = v;
        break;
      case 2:
        ok = read_double(in, type, out.time);
        break;
      case 3:
        ok = read_double(in, type, out.dt_limit);
        break;
      case 4:
        ok = read_double(in, type, out.dt_cfl);
        break;
      case 5:
        ok = read_double(in, type, out.dt_viscous);
        break;
      case 6:
        ok = read_double(in, type, out.dt_force);
        break;
      case 7:
        ok = read_packed_varints(in, type, out.overlap_id);
        break;
      case 8:
        ok = read_packed_doubles(in, type, out.overlap_position);
        break;
      case 9:
        ok = read_packed_doubles(in, type, out.overlap_velocity);
        break;
      case 10:
        ok = read_packed_doubles(in, type, out.overlap_density);
        break;
      case 11:
        ok = read_packed_doubles(in, type, out.overlap_mass);
        break;
      case 12:
        ok = read_packed_doubles(in, type, out.overlap_porosity);
        break;
      case 13:
        ok = read_packed_varints(in, type, out.overlap_material);
        break;
      case 14: {
        std::uint32_t length = 0;
        ok = type == kDelimited && in.ReadVarint32(&length) &&
             static_cast<std::size_t>(in.CurrentPosition()) + length <= size &&
             scratch.ParseFromArray(data + in.CurrentPosition(), static_cast<int>(length)) &&
             in.Skip(static_cast<int>(length));
        if (ok) from_wire(scratch, out.diagnostics);
        diagnostics_read = true;
        break;
      }
      case 15:
        ok = read_packed_doubles(in, type, out.region_min);
        break;
      case 16:
        ok = read_packed_doubles(in, type, out.region_max);
        break;
      case 17:
        ok = read_varint(in, type, v);
        out.checkpoint_written = static_cast<std::uint32_t>(v);
        break;
      case 18:
        ok = read_varint(in, type, v);
        out.delta.same_set = v != 0;
        break;
      case 19:
        ok = read_varint(in, type, v);
        out.delta.unchanged_tail = static_cast<std::uint32_t>(v);
        break;
      case 20:
        ok = read_packed_doubles(in, type, out.overlap_update_base);
        break;
      case 21:
        ok = read_packed_doubles(in, type, out.overlap_update_rate);
        break;
      default:
        ok = WireFormatLite::SkipField(&in, tag);
    }
    if (!ok) return false;
  }
  if (static_cast<std::size_t>(in.CurrentPosition()) != size) return false;
  if (!diagnostics_read) {
    scratch.Clear();
    from_wire(scratch, out.diagnostics);
  }
  return true;
}

bool read_command_body(const std::uint8_t* data, std::size_t size, coupling::StepCommand& out) {
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  CodedInputStream in(data, static_cast<int>(size));
  in.PushLimit(static_cast<int>(size));  // bytes_left() measures against it
  out.step = 0;
  out.time = out.dt = 0.0;
  out.write_output = out.stop = out.write_checkpoint = false;
  out.output_index = out.checkpoint_index = 0;
  out.interaction_acceleration.clear();
  out.interaction_rate.clear();
  out.saturation.clear();
  out.porosity.clear();
  out.wall_speed.clear();
  out.load_force.clear();
  out.other_region_min.clear();
  out.other_region_max.clear();
  for (;;) {
    const std::uint32_t tag = in.ReadTag();
    if (tag == 0) break;
    const WireType type = WireFormatLite::GetTagWireType(tag);
    std::uint64_t v = 0;
    bool ok = true;
    switch (WireFormatLite::GetTagFieldNumber(tag)) {
      case 1:
        ok = read_varint(in, type, v);
        out.step = v;
        break;
      case 2:
        ok = read_double(in, type, out.time);
        break;
      case 3:
        ok = read_double(in, type, out.dt);
        break;
      case 4:
        ok = read_varint(in, type, v);
        out.write_output = v != 0;
        break;
      case 5:
        ok = read_varint(in, type, v);
        out.output_index = static_cast<std::uint32_t>(v);
        break;
      case 6:
        ok = read_varint(in, type, v);
        out.stop = v != 0;
        break;
      case 7:
        ok = read_packed_doubles(in, type, out.interaction_acceleration);
        break;
      case 8:
        ok = read_packed_doubles(in, type, out.saturation);
        break;
      case 9:
        ok = read_packed_doubles(in, type, out.other_region_min);
        break;
      case 10:
        ok = read_packed_doubles(in, type, out.other_region_max);
        break;
      case 11:
        ok = read_varint(in, type, v);
        out.write_checkpoint = v != 0;
        break;
      case 12:
        ok = read_varint(in, type, v);
        out.checkpoint_index = static_cast<std::uint32_t>(v);
        break;
      case 13:
        ok = read_packed_doubles(in, type, out.interaction_rate);
        break;
      case 14:
        ok = read_packed_doubles(in, type, out.porosity);
        break;
      case 15:
        ok = read_packed_doubles(in, type, out.wall_speed);
        break;
      case 16:
        ok = read_packed_doubles(in, type, out.load_force);
        break;
      default:
        ok = WireFormatLite::SkipField(&in, tag);
    }
    if (!ok) return false;
  }
  return static_cast<std::size_t>(in.CurrentPosition()) == size;
}

}  // namespace porosph::wire
