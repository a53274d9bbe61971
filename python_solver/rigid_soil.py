#!/usr/bin/python3
"""rigid_soil.py: a PoroSPH soil solver in Python, speaking proto/porosph.proto itself.

The soil is a rigid porous skeleton: its particles sit on the lattice of the scene's soil blocks
and never move. Each step it reports the particles inside the overlap zone the coupler asked for,
with zero velocity, their density, mass, porosity and material, and no time-step limit of its own;
the interaction accelerations the coupler returns are checked for size and otherwise ignored
(the skeleton absorbs them). With h5py it writes soil.h5 (the layout of docs/solver-protocol.md,
"Snapshots") with a field of its own, overlap_steps (how many steps each particle spent in the
overlap zone), and declares its fields with its first state, so run.xdmf lists them; without
h5py, or with --no-snapshots, it writes none, and the coupler leaves the soil out of run.xdmf. The walk-through of this
file is docs/solver-protocol.md.

  rigid_soil.py [--endpoint E] [--connect-timeout S] [--protocol-version V] [--no-snapshots]
                [--fail-at-step N]

Started by the coupler (soil.solver = "build/python/rigid_soil.py", or --set soil.solver=...),
it connects to --endpoint or $POROSPH_ENDPOINT and sends the run token of $POROSPH_RUN_TOKEN with
every message (the coupler drops messages without it; docs/protocol.md). --protocol-version announces another version in
Hello (to see the coupler refuse it); --fail-at-step N reports an Error instead of the state of
step N. It needs porosph_pb2.py (protoc --python_out, done by the build into build/python/) on
its module path, and python3-zmq / python3-protobuf.

Exit codes: 0 the coupler ended the run, 1 the coupler refused, stopped or lost this solver,
2 bad arguments, 3 this solver failed (after telling the coupler why).
"""

import argparse
import math
import os
import sys
import time
import tomllib

import zmq

try:
    import h5py
    import numpy
except ImportError:  # no snapshot file: the run goes on without one
    h5py = None

try:
    import porosph_pb2 as wire
except ImportError as error:
    sys.exit("rigid_soil.py: cannot import porosph_pb2 (%s): generate it with "
             "`protoc --python_out=DIR -I proto proto/porosph.proto` and put DIR on PYTHONPATH "
             "(the build does this in build/python/)" % error)

PROTOCOL_VERSION = 1
PHASE = "soil"
SOLVER_NAME = "porosph-python-rigid-soil"
SOLVER_VERSION = "0.1.0"
LINGER_MILLISECONDS = 1000  # how long a last message may take to leave when the solver exits
LATTICE_TOLERANCE = 1e-9    # relative to dp, as sph/geometry.cpp
# Soil observables measure the free particles; the skeleton has none, so each kind takes its
# empty-set value (sph/observables.h): NaN for these, 0 for the others.
NAN_ON_EMPTY_SET = {"front_position", "max_height", "mean_field", "pressure_at"}


class CouplerGone(Exception):
    """The coupler sent Error or Shutdown, or did not answer in time."""


class UnsupportedScene(ValueError):
    """A scene this minimal solver cannot represent."""


class CouplerConnection:
    """One DEALER socket to the coupler's ROUTER; one serialised Envelope per ZeroMQ message."""

    def __init__(self, endpoint, run_token):
        self.context = zmq.Context()
        self.socket = self.context.socket(zmq.DEALER)
        self.socket.setsockopt(zmq.LINGER, LINGER_MILLISECONDS)
        self.socket.setsockopt(zmq.IPV6, 1)  # tcp://[::1]:P, host names with IPv6 addresses
        self.run_token = run_token  # the run's secret, carried by every message
        self.socket.connect(endpoint)
        self.seconds = 0.0  # spent sending and waiting (the Goodbye's communication_seconds)

    def send(self, body, message):
        """Sends `message` as the Envelope field `body` ("hello", "state", "error", ...)."""
        start = time.monotonic()
        envelope = wire.Envelope(run_token=self.run_token)
        getattr(envelope, body).CopyFrom(message)
        self.socket.send(envelope.SerializeToString())
        self.seconds += time.monotonic() - start

    def receive(self, timeout_seconds):
        """The next Envelope, or CouplerGone after `timeout_seconds` of silence."""
        start = time.monotonic()
        ready = self.socket.poll(int(timeout_seconds * 1000))
        self.seconds += time.monotonic() - start
        if not ready:
            raise CouplerGone("no answer from the coupler within %g s" % timeout_seconds)
        frames = self.socket.recv_multipart()
        envelope = wire.Envelope()
        envelope.ParseFromString(frames[-1])
        return envelope

    def report_error(self, message, step, sim_time, particle_id=-1):
        """Tells the coupler this solver failed; it then stops the run with `message`."""
        error = wire.Error(phase=PHASE, message=message, step=step, time=sim_time,
                           particle_id=particle_id)
        self.send("error", error)

    def close(self):
        self.socket.close()  # waits up to the linger period for unsent messages
        self.context.term()


def refuse_unexpected(envelope, expected):
    """Raises CouplerGone for an Error or Shutdown (or anything but `expected`) from the coupler."""
    kind = envelope.WhichOneof("body")
    if kind == "error":
        raise CouplerGone("the coupler reported an error: " + envelope.error.message)
    if kind == "shutdown":
        raise CouplerGone("the coupler shut down the run: " + envelope.shutdown.reason)
    raise CouplerGone("protocol violation: expected %s from the coupler, got %s" % (expected, kind))


def lattice_axis(lo, hi, dp):
    """Centres lo + (i + 1/2) dp below hi (sph/geometry.cpp lattice_count)."""
    count = max(0, math.ceil((hi - lo) / dp - 0.5 - LATTICE_TOLERANCE)) if hi > lo else 0
    return [lo + (i + 0.5) * dp for i in range(count)]


def box_lattice(lo, hi, dp):
    """Every lattice point of the box [lo, hi], first axis fastest."""
    points = [()]
    for k in range(len(lo)):
        points = [p[:k] + (x,) + p[k:] for x in lattice_axis(lo[k], hi[k], dp) for p in points]
    return points


def inside_box(x, lo, hi):
    return all(lo[k] <= x[k] <= hi[k] for k in range(len(x)))


class RigidSkeleton:
    """The particles of the scene's soil blocks, on the built-in soil_solver's lattice."""

    def __init__(self, scene):
        run, soil = scene["run"], scene["soil"]
        dimension, dp = run["dimension"], run["dp"]
        periodic = run.get("periodic") or [False] * dimension
        domain_min, domain_max = scene["domain"]["min"], scene["domain"]["max"]
        walls = [w for w in scene.get("walls", []) if not w.get("phases") or PHASE in w["phases"]]
        if walls:
            raise UnsupportedScene("walls acting on soil are not supported by this minimal solver")
        materials = {m["name"]: index for index, m in enumerate(soil["materials"])}
        self.dimension = dimension
        self.position, self.density, self.mass, self.porosity, self.material = [], [], [], [], []
        blocks = soil["blocks"]
        for b, block in enumerate(blocks):
            if block["shape"] != "box":
                raise UnsupportedScene("soil block %d is a %s; this minimal solver fills boxes only"
                                       % (b, block["shape"]))
            if block["material"] not in materials:
                raise UnsupportedScene("soil block %d: unknown material '%s'"
                                       % (b, block["material"]))
            index = materials[block["material"]]
            m = soil["materials"][index]
            for x in box_lattice(block["min"], block["max"], dp):
                # Outside the domain (or on its upper face of a periodic axis): not a particle.
                if any(x[k] < domain_min[k] or (x[k] >= domain_max[k] if periodic[k]
                                                else x[k] > domain_max[k])
                       for k in range(dimension)):
                    continue
                if any(inside_box(x, e["min"], e["max"]) for e in blocks[:b]):
                    continue  # an earlier block holds this point
                self.position.append(x)
                self.density.append(m["density"])
                self.mass.append(m["density"] * dp ** dimension)
                self.porosity.append(m["porosity"])
                self.material.append(index)
        if self.position:
            self.region_min = [min(x[k] for x in self.position) for k in range(dimension)]
            self.region_max = [max(x[k] for x in self.position) for k in range(dimension)]
        else:  # an empty region (min > max): the coupler then gives the water no overlap zone
            self.region_min, self.region_max = [math.inf] * dimension, [-math.inf] * dimension

    def inside(self, zone_min, zone_max):
        """Indices of the particles in the closed box [zone_min, zone_max] (empty zone: none)."""
        if len(zone_min) != self.dimension or len(zone_max) != self.dimension:
            return []
        return [i for i, x in enumerate(self.position) if inside_box(x, zone_min, zone_max)]


class SnapshotFile:
    """soil.h5: /snapshots/NNNNNN groups with a `time` attribute and one dataset per field."""

    # name, components (0: the dimension), HDF5 / XDMF type, unit
    FIELDS = [("velocity", 0, "Float", "m/s"), ("density", 1, "Float", "kg/m^3"),
              ("porosity", 1, "Float", ""), ("id", 1, "Int", ""), ("material", 1, "Int", ""),
              ("fixed", 1, "UChar", ""), ("overlap_steps", 1, "Int", "")]

    def __init__(self, path, skeleton):
        self.file = h5py.File(path, "w")
        self.skeleton = skeleton
        self.overlap_steps = numpy.zeros(len(skeleton.position), dtype=numpy.int64)

    def declare(self, diagnostics):
        """The fields besides position, sent with the first state (porosph.proto, OutputField)."""
        for name, components, number_type, unit in self.FIELDS:
            diagnostics.output_fields.add(name=name, number_type=number_type, unit=unit,
                                          components=components or self.skeleton.dimension)

    def count(self, overlap):
        self.overlap_steps[overlap] += 1

    def write(self, index, sim_time):
        k = self.skeleton
        n, d = len(k.position), k.dimension
        values = {"position": numpy.array(k.position, dtype=float).reshape(n, d),
                  "velocity": numpy.zeros((n, d)), "density": numpy.array(k.density),
                  "porosity": numpy.array(k.porosity), "id": numpy.arange(n, dtype=numpy.int64),
                  "material": numpy.array(k.material, dtype=numpy.int64),
                  "fixed": numpy.ones(n, dtype=numpy.uint8), "overlap_steps": self.overlap_steps}
        group = self.file.create_group("/snapshots/%06d" % index)
        group.attrs["time"] = sim_time
        for name, data in values.items():
            group.create_dataset(name, data=data)
        self.file.flush()

    def close(self):
        self.file.close()


def fill_state(state, skeleton, overlap, observables):
    """The overlap particles (zero velocity), the region, no dt limit and the diagnostics."""
    d = skeleton.dimension
    state.dt_limit = state.dt_cfl = state.dt_viscous = state.dt_force = math.inf
    for name in ("overlap_id", "overlap_position", "overlap_velocity", "overlap_density",
                 "overlap_mass", "overlap_porosity", "overlap_material", "region_min",
                 "region_max"):
        state.ClearField(name)
    state.overlap_id.extend(overlap)
    state.overlap_position.extend(c for i in overlap for c in skeleton.position[i])
    state.overlap_velocity.extend([0.0] * (d * len(overlap)))
    state.overlap_density.extend(skeleton.density[i] for i in overlap)
    state.overlap_mass.extend(skeleton.mass[i] for i in overlap)
    state.overlap_porosity.extend(skeleton.porosity[i] for i in overlap)
    state.overlap_material.extend(skeleton.material[i] for i in overlap)
    state.region_min.extend(skeleton.region_min)
    state.region_max.extend(skeleton.region_max)
    g = state.diagnostics
    g.particle_count = len(skeleton.position)
    g.free_count = 0  # mass, momentum, energy and speed are of the free particles: all zero
    g.ClearField("momentum")
    g.momentum.extend([0.0] * d)
    for o in observables:
        g.observables[o["name"]] = math.nan if o["kind"] in NAN_ON_EMPTY_SET else 0.0


def check_command(command, step, overlap_count, dimension):
    """A message saying what is wrong with the command, or None."""
    if command.step != step:
        return "bad command: step %d, expected %d" % (command.step, step)
    n = len(command.interaction_acceleration)
    if n not in (0, overlap_count * dimension):
        return "bad command: %d acceleration values for %d overlap particles" % (n, overlap_count)
    n = len(command.saturation)
    if n not in (0, overlap_count):
        return "bad command: %d saturation values for %d overlap particles" % (n, overlap_count)
    if not command.stop and not command.dt > 0:
        return "bad command: dt = %g" % command.dt
    return None


def run(options, connection):
    """Hello, Setup, the step loop, Goodbye. Returns the exit code."""
    started = time.monotonic()
    connection.send("hello", wire.Hello(protocol_version=options.protocol_version, phase=PHASE,
                                        solver_name=SOLVER_NAME, solver_version=SOLVER_VERSION,
                                        pid=os.getpid()))
    envelope = connection.receive(options.connect_timeout)
    if envelope.WhichOneof("body") == "error":
        raise CouplerGone("the coupler refused this soil solver: " + envelope.error.message)
    if envelope.WhichOneof("body") != "setup":
        refuse_unexpected(envelope, "Setup")
    setup = envelope.setup
    if setup.protocol_version != options.protocol_version:
        raise CouplerGone("the coupler speaks protocol version %d, this solver %d"
                          % (setup.protocol_version, options.protocol_version))
    timeout = setup.timeout_seconds if setup.timeout_seconds > 0 else 60.0
    try:
        scene = tomllib.loads(setup.scene_toml)
        skeleton = RigidSkeleton(scene)
    except (UnsupportedScene, tomllib.TOMLDecodeError, KeyError) as error:
        connection.report_error("cannot build the rigid skeleton: %s" % error, 0, 0.0)
        return 3
    observables = [o for o in scene.get("observables", []) if o["phase"] == PHASE]
    snapshots = None
    if h5py is not None and not options.no_snapshots:
        snapshots = SnapshotFile(os.path.join(setup.output_dir, "soil.h5"), skeleton)
    try:
        return step_loop(options, connection, skeleton, observables, snapshots, timeout, started)
    finally:
        if snapshots is not None:
            snapshots.close()


def step_loop(options, connection, skeleton, observables, snapshots, timeout, started):
    """The states and commands until the coupler stops the run, then Goodbye."""

    step, sim_time = 0, 0.0
    zone = ([], [])
    overlap = []
    state = wire.StepState()
    if snapshots is not None:
        snapshots.declare(state.diagnostics)  # with the first state only
    physics_seconds = 0.0
    while True:
        work_start = time.monotonic()
        if step == options.fail_at_step:
            connection.report_error("injected failure at step %d" % step, step, sim_time)
            return 3
        state.step, state.time = step, sim_time
        fill_state(state, skeleton, overlap, observables)
        state.diagnostics.physics_seconds = time.monotonic() - work_start
        physics_seconds += state.diagnostics.physics_seconds
        connection.send("state", state)
        state.diagnostics.ClearField("output_fields")

        envelope = connection.receive(timeout)
        if envelope.WhichOneof("body") != "command":
            refuse_unexpected(envelope, "StepCommand")
        command = envelope.command
        problem = check_command(command, step, len(overlap), skeleton.dimension)
        if problem:
            connection.report_error(problem, step, sim_time)
            return 3
        if command.write_output and snapshots is not None:
            snapshots.write(command.output_index, sim_time)  # the state before advancing
        if command.stop:
            break
        # write_checkpoint: not supported, so checkpoint_written stays 0 and the coupler turns
        # checkpoints off for the run.
        new_zone = (list(command.other_region_min), list(command.other_region_max))
        if new_zone != zone:
            zone = new_zone
            overlap = skeleton.inside(*zone)
        if snapshots is not None:
            snapshots.count(overlap)
        sim_time += command.dt  # exactly the coupler's dt: it checks the time of every state
        step += 1

    connection.send("goodbye", wire.Goodbye(wall_seconds=time.monotonic() - started,
                                            physics_seconds=physics_seconds,
                                            communication_seconds=connection.seconds))
    return 0


def parse_options(argv):
    parser = argparse.ArgumentParser(description="PoroSPH rigid porous skeleton soil solver "
                                                 "(Python, started by `coupler run`)")
    parser.add_argument("--endpoint", default="", help="coupler endpoint "
                        "(default: $POROSPH_ENDPOINT)")
    parser.add_argument("--connect-timeout", type=float, default=60.0,
                        help="seconds to wait for Setup after Hello")
    parser.add_argument("--protocol-version", type=int, default=PROTOCOL_VERSION,
                        help="version announced in Hello (tests of the coupler's check)")
    parser.add_argument("--no-snapshots", action="store_true",
                        help="write no soil.h5 (the coupler then leaves the soil out of run.xdmf)")
    parser.add_argument("--fail-at-step", type=int, default=-1,
                        help="report an Error instead of the state of this step (tests)")
    options = parser.parse_args(argv)
    options.endpoint = options.endpoint or os.environ.get("POROSPH_ENDPOINT", "")
    if not options.endpoint:
        parser.error("no coupler endpoint: pass --endpoint or set POROSPH_ENDPOINT "
                     "(the coupler does when it starts this solver)")
    return options


def main(argv):
    options = parse_options(argv)
    connection = CouplerConnection(options.endpoint, os.environ.get("POROSPH_RUN_TOKEN", ""))
    try:
        return run(options, connection)
    except CouplerGone as error:
        print("rigid_soil.py: %s" % error, file=sys.stderr)
        return 1
    except Exception as error:  # a bug or a scene it cannot read: tell the coupler, then fail
        message = "%s: %s" % (type(error).__name__, error)
        connection.report_error(message, 0, 0.0)
        print("rigid_soil.py: %s" % message, file=sys.stderr)
        return 3
    finally:
        connection.close()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
