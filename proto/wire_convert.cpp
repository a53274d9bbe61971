#include "proto/wire_convert.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/wire_format_lite.h>

#include <algorithm>
#include <iterator>
#include <limits>

#include "proto/state_delta.h"

namespace porosph::wire {
namespace {

template <typename T, typename Vec>
void assign(google::protobuf::RepeatedField<T>* out, const Vec& in) {
  out->Assign(in.begin(), in.end());
}

template <typename T, typename Vec>
void assign(Vec& out, const google::protobuf::RepeatedField<T>& in) {
  out.assign(in.begin(), in.end());
}

}  // namespace

void to_wire(const coupling::Diagnostics& in, Diagnostics& out) {
  out.set_particle_count(in.particle_count);
  out.set_free_count(in.free_count);
  out.set_removed_count(in.removed_count);
  out.set_mass(in.mass);
  out.set_kinetic_energy(in.kinetic_energy);
  out.set_max_speed(in.max_speed);
  out.set_physics_seconds(in.physics_seconds);
  out.set_wall_seconds(in.wall_seconds);
  out.set_communication_seconds(in.communication_seconds);
  out.set_inflow_mass(in.inflow_mass);
  out.set_outflow_mass(in.outflow_mass);
  out.set_neighbours_per_particle(in.neighbours_per_particle);
  assign(out.mutable_momentum(), in.momentum);
  out.mutable_terms()->Clear();
  for (const std::string& term : in.terms) out.add_terms(term);
  out.mutable_impulse_sources()->Clear();
  for (const std::string& source : in.impulse_sources) out.add_impulse_sources(source);
  out.mutable_output_fields()->Clear();
  for (const coupling::OutputField& field : in.output_fields) {
    OutputField* f = out.add_output_fields();
    f->set_name(field.name);
    f->set_components(field.components);
    f->set_number_type(field.number_type);
    f->set_unit(field.unit);
  }
  assign(out.mutable_external_impulse(), in.external_impulse);
  assign(out.mutable_balance_momentum(), in.balance_momentum);
  auto& observables = *out.mutable_observables();
  // Update in place (no node churn when the names stay the same), then drop stale names.
  for (const auto& [name, value] : in.observables) observables[name] = value;
  if (static_cast<std::size_t>(observables.size()) != in.observables.size()) {
    for (auto it = observables.begin(); it != observables.end();) {
      it = in.observables.count(it->first) ? std::next(it) : observables.erase(it);
    }
  }
}

void from_wire(const Diagnostics& in, coupling::Diagnostics& out) {
  out.particle_count = in.particle_count();
  out.free_count = in.free_count();
  out.removed_count = in.removed_count();
  out.mass = in.mass();
  out.kinetic_energy = in.kinetic_energy();
  out.max_speed = in.max_speed();
  out.physics_seconds = in.physics_seconds();
  out.wall_seconds = in.wall_seconds();
  out.communication_seconds = in.communication_seconds();
  out.inflow_mass = in.inflow_mass();
  out.outflow_mass = in.outflow_mass();
  out.neighbours_per_particle = in.neighbours_per_particle();
  assign(out.momentum, in.momentum());
  out.terms.assign(in.terms().begin(), in.terms().end());
  out.impulse_sources.assign(in.impulse_sources().begin(), in.impulse_sources().end());
  out.output_fields.clear();
  for (const OutputField& f : in.output_fields())
    out.output_fields.push_back({f.name(), f.components(), f.number_type(), f.unit()});
  assign(out.external_impulse, in.external_impulse());
  assign(out.balance_momentum, in.balance_momentum());
  for (const auto& [name, value] : in.observables()) {
    auto it = out.observables.find(name);
    if (it != out.observables.end()) {
      it->second = value;
    } else {
      out.observables.emplace(name, value);
    }
  }
  if (out.observables.size() != static_cast<std::size_t>(in.observables().size())) {
    for (auto it = out.observables.begin(); it != out.observables.end();) {
      it = in.observables().count(it->first) ? std::next(it) : out.observables.erase(it);
    }
  }
}

namespace {

const google::protobuf::MessageLite& body_message(const Envelope& envelope) {
  switch (envelope.body_case()) {
    case Envelope::kHello:
      return envelope.hello();
    case Envelope::kSetup:
      return envelope.setup();
    case Envelope::kState:
      return envelope.state();
    case Envelope::kCommand:
      return envelope.command();
    case Envelope::kError:
      return envelope.error();
    case Envelope::kGoodbye:
      return envelope.goodbye();
    case Envelope::kShutdown:
      return envelope.shutdown();
    default:
      return envelope;
  }
}

/// Clear() without freeing sub-messages: a parse merges into the same objects again.
void clear_keeping_storage(StepState& message) {
  Diagnostics* diagnostics = message.has_diagnostics() ? message.release_diagnostics() : nullptr;
  message.Clear();
  if (diagnostics != nullptr) {
    diagnostics->Clear();
    message.set_allocated_diagnostics(diagnostics);
  }
}
void clear_keeping_storage(StepCommand& message) { message.Clear(); }

template <typename Hot>
bool parse_envelope_into(const void* data, std::size_t size, int hot_field, Hot& hot,
                         Envelope& envelope, Envelope::BodyCase& body) {
  using google::protobuf::internal::WireFormatLite;
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  const int total = static_cast<int>(size);
  // Our senders write exactly one field: the oneof body. Read its tag and length; anything else
  // (e.g. a foreign sender adding unknown fields) takes the general path below.
  google::protobuf::io::CodedInputStream in(bytes, total);
  const std::uint32_t tag = in.ReadTag();
  std::uint32_t length = 0;
  if (WireFormatLite::GetTagFieldNumber(tag) == hot_field &&
      WireFormatLite::GetTagWireType(tag) == WireFormatLite::WIRETYPE_LENGTH_DELIMITED &&
      in.ReadVarint32(&length) && in.CurrentPosition() + std::int64_t{length} == total) {
    body = static_cast<Envelope::BodyCase>(hot_field);
    clear_keeping_storage(hot);
    google::protobuf::io::CodedInputStream body_bytes(bytes + in.CurrentPosition(),
                                                      static_cast<int>(length));
    return hot.MergeFromCodedStream(&body_bytes) && body_bytes.ConsumedEntireMessage();
  }
  if (!envelope.ParseFromArray(bytes, total)) return false;
  body = envelope.body_case();
  if (body == hot_field) {  // rare: the hot body came with extra fields
    clear_keeping_storage(hot);
    hot.MergeFrom(static_cast<const Hot&>(body_message(envelope)));
  }
  return true;
}

}  // namespace

bool parse_envelope(const void* data, std::size_t size, StepState& hot, Envelope& envelope,
                    Envelope::BodyCase& body) {
  return parse_envelope_into(data, size, Envelope::kStateFieldNumber, hot, envelope, body);
}

bool parse_envelope(const void* data, std::size_t size, StepCommand& hot, Envelope& envelope,
                    Envelope::BodyCase& body) {
  return parse_envelope_into(data, size, Envelope::kCommandFieldNumber, hot, envelope, body);
}

void to_wire(const coupling::StepState& in, const coupling::StateDelta& delta, StepState& out) {
  out.set_step(in.step);
  out.set_time(in.time);
  out.set_dt_limit(in.dt_limit);
  out.set_dt_cfl(in.dt_cfl);
  out.set_dt_viscous(in.dt_viscous);
  out.set_dt_force(in.dt_force);
  out.set_overlap_same_set(delta.same_set);
  out.set_overlap_unchanged_tail(delta.unchanged_tail);
  const std::vector<std::int64_t> none_id;
  const std::vector<double> none;
  const std::vector<std::int32_t> none_material;
  assign(out.mutable_overlap_id(), delta.same_set ? none_id : in.overlap_id);
  assign(out.mutable_overlap_mass(), delta.same_set ? none : in.overlap_mass);
  assign(out.mutable_overlap_material(), delta.same_set ? none_material : in.overlap_material);
  const coupling::SentParticles sent(in, delta);
  const auto per_step = [&](google::protobuf::RepeatedField<double>* field,
                            const std::vector<double>& values, std::size_t per_particle) {
    const auto count = static_cast<std::ptrdiff_t>(sent.count(values, per_particle));
    field->Assign(values.begin(), values.begin() + count);
  };
  per_step(out.mutable_overlap_position(), in.overlap_position, sent.dimension);
  per_step(out.mutable_overlap_velocity(), in.overlap_velocity, sent.dimension);
  per_step(out.mutable_overlap_density(), in.overlap_density, 1);
  per_step(out.mutable_overlap_porosity(), in.overlap_porosity, 1);
  per_step(out.mutable_overlap_update_base(), in.overlap_update_base, sent.dimension);
  per_step(out.mutable_overlap_update_rate(), in.overlap_update_rate, sent.dimension);
  assign(out.mutable_region_min(), in.region_min);
  assign(out.mutable_region_max(), in.region_max);
  to_wire(in.diagnostics, *out.mutable_diagnostics());
  out.set_checkpoint_written(in.checkpoint_written);
}

void to_wire(const coupling::StepState& in, StepState& out) {
  to_wire(in, coupling::StateDelta{}, out);
}

void from_wire(const StepState& in, coupling::StepState& out) {
  out.step = in.step();
  out.time = in.time();
  out.dt_limit = in.dt_limit();
  out.dt_cfl = in.dt_cfl();
  out.dt_viscous = in.dt_viscous();
  out.dt_force = in.dt_force();
  assign(out.overlap_id, in.overlap_id());
  assign(out.overlap_position, in.overlap_position());
  assign(out.overlap_velocity, in.overlap_velocity());
  assign(out.overlap_density, in.overlap_density());
  assign(out.overlap_mass, in.overlap_mass());
  assign(out.overlap_porosity, in.overlap_porosity());
  assign(out.overlap_material, in.overlap_material());
  assign(out.overlap_update_base, in.overlap_update_base());
  assign(out.overlap_update_rate, in.overlap_update_rate());
  assign(out.region_min, in.region_min());
  assign(out.region_max, in.region_max());
  from_wire(in.diagnostics(), out.diagnostics);
  out.checkpoint_written = in.checkpoint_written();
  out.delta.same_set = in.overlap_same_set();
  out.delta.unchanged_tail = in.overlap_unchanged_tail();
}

void to_wire(const coupling::StepCommand& in, StepCommand& out) {
  out.set_step(in.step);
  out.set_time(in.time);
  out.set_dt(in.dt);
  out.set_write_output(in.write_output);
  out.set_output_index(in.output_index);
  out.set_stop(in.stop);
  assign(out.mutable_interaction_acceleration(), in.interaction_acceleration);
  assign(out.mutable_interaction_rate(), in.interaction_rate);
  assign(out.mutable_saturation(), in.saturation);
  assign(out.mutable_porosity(), in.porosity);
  assign(out.mutable_wall_speed(), in.wall_speed);
  assign(out.mutable_load_force(), in.load_force);
  assign(out.mutable_other_region_min(), in.other_region_min);
  assign(out.mutable_other_region_max(), in.other_region_max);
  out.set_write_checkpoint(in.write_checkpoint);
  out.set_checkpoint_index(in.checkpoint_index);
}

void from_wire(const StepCommand& in, coupling::StepCommand& out) {
  out.step = in.step();
  out.time = in.time();
  out.dt = in.dt();
  out.write_output = in.write_output();
  out.output_index = in.output_index();
  out.stop = in.stop();
  assign(out.interaction_acceleration, in.interaction_acceleration());
  assign(out.interaction_rate, in.interaction_rate());
  assign(out.saturation, in.saturation());
  assign(out.porosity, in.porosity());
  assign(out.wall_speed, in.wall_speed());
  assign(out.load_force, in.load_force());
  assign(out.other_region_min, in.other_region_min());
  assign(out.other_region_max, in.other_region_max());
  out.write_checkpoint = in.write_checkpoint();
  out.checkpoint_index = in.checkpoint_index();
}

void to_wire(const coupling::SetupData& in, Setup& out) {
  out.set_phase(in.phase);
  out.set_scene_toml(in.scene_toml);
  out.set_scene_name(in.scene_name);
  out.set_output_dir(in.output_dir);
  out.set_dimension(static_cast<std::uint32_t>(in.dimension));
  out.set_dp(in.dp);
  out.set_h(in.h);
  out.set_dt0(in.dt0);
  out.set_end_time(in.end_time);
  assign(out.mutable_gravity(), in.gravity);
  out.set_timeout_seconds(in.timeout_seconds);
  out.set_restore_checkpoint(in.restore_checkpoint);
  out.set_resume_output_index(in.resume_output_index);
}

void from_wire(const Setup& in, coupling::SetupData& out) {
  out.phase = in.phase();
  out.scene_toml = in.scene_toml();
  out.scene_name = in.scene_name();
  out.output_dir = in.output_dir();
  out.dimension = static_cast<int>(in.dimension());
  out.dp = in.dp();
  out.h = in.h();
  out.dt0 = in.dt0();
  out.end_time = in.end_time();
  assign(out.gravity, in.gravity());
  out.timeout_seconds = in.timeout_seconds();
  out.restore_checkpoint = in.restore_checkpoint();
  out.resume_output_index = in.resume_output_index();
}

void to_wire(const coupling::Timing& in, Goodbye& out) {
  out.set_wall_seconds(in.wall_seconds);
  out.set_physics_seconds(in.physics_seconds);
  out.set_communication_seconds(in.communication_seconds);
}

void from_wire(const Goodbye& in, coupling::Timing& out) {
  out.wall_seconds = in.wall_seconds();
  out.physics_seconds = in.physics_seconds();
  out.communication_seconds = in.communication_seconds();
}

}  // namespace porosph::wire
