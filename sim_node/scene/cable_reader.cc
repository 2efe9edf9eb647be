#include "scene/cable_reader.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/vessel_motion.h"
#include "core/winch.h"
#include "scene/body_reader.h"
#include "scene/line_type_reader.h"

namespace towsim::scene::internal {
namespace {

constexpr double kStraightMaxStretch = 0.01;  // initial: straight may stretch the cable by 1%
constexpr double kVerticalTolerance = 1e-3;   // initial: vertical end offset, relative to length

// a percentage for messages, 3 significant digits: 33.3
std::string FormatPercent(double fraction) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", 100.0 * fraction);
  return buffer;
}

struct EndInput {
  core::CableEnd end;
  Field field;  // cable.start or cable.end, for messages
};

core::CableLoads ReadLoads(const Field& field) {
  // a list naming the loads that are on; each at most once
  if (!field.node().IsSequence()) field.Fail("must be a list, e.g. [gravity, buoyancy, drag]");
  static const std::vector<std::string> kNames = {"gravity", "buoyancy", "drag", "added_mass",
                                                  "bending"};
  core::CableLoads loads{false, false, false, false, false};
  bool* const flags[] = {&loads.gravity, &loads.buoyancy, &loads.drag, &loads.added_mass,
                         &loads.bending};
  for (const Field& item : field.Items()) {
    bool& on = *flags[item.Choice(kNames)];
    if (on) item.Fail("duplicate load (already listed)");
    on = true;
  }
  return loads;
}

EndInput ReadEnd(const Field& field, const core::Model& model) {
  const MapReader map(field, MapKind::kEnd);
  EndInput input{core::CableEnd{}, field};
  core::CableEnd& end = input.end;

  // exactly one of fixed, driven, free, body
  std::string kinds;
  int count = 0;
  for (const char* kind : {"fixed", "driven", "free", "body"}) {
    if (!map.Has(kind)) continue;
    kinds += (count++ ? " and " : "") + std::string(kind);
  }
  if (count != 1) {
    field.Fail(
        "must be exactly one of {fixed: [x, y, z]}, {driven: {position, velocity}}, "
        "{free: true}, {body: <name>, at: [x, y, z]}" +
        (count > 1 ? " (it has " + kinds + ")" : std::string()));
  }
  // slope goes with fixed, at with body
  if (map.Has("slope") && !map.Has("fixed")) map.Get("slope").Fail("applies only to a fixed end");
  if (map.Has("at") && !map.Has("body")) map.Get("at").Fail("applies only to a body end");

  if (map.Has("fixed")) {
    end.kind = core::EndKind::kFixed;
    end.position = map.Vector("fixed");
    if (map.Has("slope")) {
      // a clamped end holds the cable direction: a non-zero vector, normalized
      const Field slope = map.Get("slope");
      const core::Vec3 direction = slope.Vector();
      if (direction.norm() == 0.0) slope.Fail("must be a non-zero direction");
      end.clamped = true;
      end.slope = direction.normalized();
    }
  } else if (map.Has("driven")) {
    end.kind = core::EndKind::kDriven;
    const MapReader driven(map.Get("driven"), MapKind::kDriven);
    if (!driven.field().node().IsMap()) driven.field().Fail("must be a map {position, velocity}");
    end.position = driven.Vector("position");
    end.velocity = driven.Vector("velocity");
  } else if (map.Has("free")) {
    // free: true (false would hold nothing)
    const Field free = map.Get("free");
    if (!free.Boolean()) free.Fail("must be true (to hold the end use fixed, driven or body)");
    end.kind = core::EndKind::kFree;
  } else {
    // the body must exist: a sphere (kSphere), a vehicle (kVehicle) or a vessel (kVessel)
    const Field body = map.Get("body");
    const BodyRef ref = FindBody(model, body.String());
    if (ref.kind == BodyRef::kNone) body.Fail("no such body (bodies: " + BodyNames(model) + ")");
    end.kind = ref.kind == BodyRef::kVehicle  ? core::EndKind::kVehicle
               : ref.kind == BodyRef::kVessel ? core::EndKind::kVessel
                                              : core::EndKind::kSphere;
    end.body = ref.index;
    end.at_B = map.Vector("at", core::Vec3::Zero());
  }
  return input;
}

bool Held(const core::CableEnd& end) { return end.kind != core::EndKind::kFree; }

// world position of a held end at t = 0: p_WB + R_WB at_B on a vehicle; a sphere's frame is
// aligned with the world
core::Vec3 EndPosition(const core::CableEnd& end, const core::Model& model) {
  if (end.kind == core::EndKind::kSphere) return model.spheres[end.body].position + end.at_B;
  if (end.kind == core::EndKind::kVehicle) {
    const core::Vehicle& v = model.vehicles[end.body];
    return v.position + core::QuaternionFromEulerZYX(v.euler) * end.at_B;
  }
  if (end.kind == core::EndKind::kVessel) {
    return core::VesselMotion(model.vessels[end.body], model.environment.waves)
        .At(0.0)
        .PointAt(end.at_B);
  }
  return end.position;
}

// the name of the body an end is attached to
const std::string& EndBodyName(const core::CableEnd& end, const core::Model& model) {
  if (end.kind == core::EndKind::kVessel) return model.vessels[end.body].name;
  return end.kind == core::EndKind::kVehicle ? model.vehicles[end.body].name
                                             : model.spheres[end.body].name;
}

bool OnBody(const core::CableEnd& end) {
  return end.kind == core::EndKind::kSphere || end.kind == core::EndKind::kVehicle ||
         end.kind == core::EndKind::kVessel;
}

void CheckEnds(const EndInput& start, const EndInput& end, const core::Model& model) {
  // at least one end held
  if (!Held(start.end) && !Held(end.end)) {
    end.field.Fail("both ends are free; hold at least one end (fixed, driven or body)");
  }
  // start and end on different bodies
  if (OnBody(start.end) && start.end.kind == end.end.kind && start.end.body == end.end.body) {
    end.field.Fail("start and end are both on body " + EndBodyName(end.end, model) +
                   "; attach them to different bodies");
  }
  // at most one driven end
  if (start.end.kind == core::EndKind::kDriven && end.end.kind == core::EndKind::kDriven) {
    end.field.Fail("both ends are driven; drive at most one end");
  }
}

void CheckInitialShape(const core::CableParams& cable, const EndInput& start, const EndInput& end,
                       const core::Model& model) {
  const double length = cable.length;
  switch (cable.initial) {
    case core::InitialShape::kVertical: {
      // the cable hangs straight down (+z) from a held start
      if (!Held(start.end)) {
        start.field.Fail(
            "initial: vertical hangs the cable from the start, so the start must be "
            "held (fixed, driven or body); use initial: static");
      }
      // a held end sits at start + [0, 0, length]
      if (!Held(end.end)) return;
      const core::Vec3 expected = EndPosition(start.end, model) + core::Vec3(0.0, 0.0, length);
      const core::Vec3 actual = EndPosition(end.end, model);
      const double offset = (actual - expected).norm();
      if (offset > kVerticalTolerance * length) {
        end.field.Fail("with initial: vertical the end must sit at start + [0, 0, length] = " +
                       FormatVector(expected) + " (within " +
                       FormatNumber(kVerticalTolerance * length) + " m), but it is at " +
                       FormatVector(actual) + ", " + FormatNumber(offset) + " m away");
      }
      return;
    }
    case core::InitialShape::kStraight: {
      // a straight line between two known points
      for (const EndInput* e : {&start, &end}) {
        if (!Held(e->end)) {
          e->field.Fail(
              "initial: straight needs both ends at known positions (fixed, driven or "
              "body); use initial: vertical or static");
        }
      }
      const core::Vec3 p_start = EndPosition(start.end, model);
      const core::Vec3 p_end = EndPosition(end.end, model);
      const double span = (p_end - p_start).norm();
      // the span is > 0 and stretches the cable by at most 1%
      if (span == 0.0) {
        end.field.Fail("with initial: straight the end must not coincide with the start " +
                       FormatVector(p_start));
      }
      if (span > (1.0 + kStraightMaxStretch) * length) {
        // the axial force that stretch takes: N = EA eps, eps = span / length - 1 (the cable's
        // EA as resolved: axial_stiffness, or youngs_modulus x A, its line type's included)
        const double strain = span / length - 1.0;
        char force[96];
        std::snprintf(force, sizeof force, "%.3g kN at EA %.3g N",
                      1e-3 * cable.axial_stiffness * strain, cable.axial_stiffness);
        end.field.Fail("with initial: straight the span from start " + FormatVector(p_start) +
                       " to end " + FormatVector(p_end) + " is " + FormatNumber(span) +
                       " m, which would stretch the " + FormatNumber(length) + " m cable by " +
                       FormatPercent(strain) + "% (at most " +
                       FormatPercent(kStraightMaxStretch) + "%): " + force);
      }
      return;
    }
    case core::InitialShape::kStatic:
      // the solver finds the shape; both-free is already excluded
      return;
  }
}

// cable.winch: the limits, each positive; min_length <= cable.length <= max_length; the start
// (the drum) held
core::WinchParams ReadWinch(const MapReader& cable, const core::CableParams& c,
                            const EndInput& start, const core::Model& model) {
  const MapReader map(cable.Get("winch"), MapKind::kWinch);
  if (!map.field().node().IsMap()) {
    map.field().Fail(
        "must be a map {min_length, max_length, max_speed, max_acceleration, brake_tension}");
  }
  core::WinchParams w;
  // its name (docs/scene_format.md "Networks"): given, or set by the scene's rule (empty here)
  w.name.clear();
  if (map.Has("name")) {
    const Field name = map.Get("name");
    w.name = name.String();
    if (!IsValidName(w.name)) name.Fail(std::string("winch names ") + kNameRule);
  }
  w.min_length = map.Number("min_length", Range::Above(0.0));
  if (w.min_length > c.length) {
    map.Get("min_length").Fail("must be <= cable.length = " + FormatNumber(c.length));
  }
  w.max_length = map.Number("max_length", Range::Above(0.0));
  if (w.max_length < c.length) {
    map.Get("max_length").Fail("must be >= cable.length = " + FormatNumber(c.length));
  }
  w.max_speed = map.Number("max_speed", Range::Above(0.0));
  // the drum element l_0 stays within [kMergeLength, kSplitLength] l_e at every instant if a
  // step changes it by at most (kSplitLength - 1 - kMergeLength) l_e: a split at the step's
  // start leaves l_0 - l_e >= kSplitLength l_e - h V - l_e, a merge l_0 + l_e <= kMergeLength
  // l_e + h V + l_e (docs/winch.md "Scene keys")
  const double element = c.length / c.elements;
  const double fraction = core::kSplitLength - 1.0 - core::kMergeLength;
  const double step = model.time.step;
  if (w.max_speed * step > fraction * element) {
    map.Get("max_speed")
        .Fail("must be <= " + FormatNumber(fraction * element / step) + " = " +
              FormatNumber(fraction) + " l_e / time.step (the drum moves at most " +
              FormatNumber(fraction) + " of an element a step, so its element stays within [" +
              FormatNumber(core::kMergeLength) + ", " + FormatNumber(core::kSplitLength) +
              "] l_e between splits and merges; l_e = cable.length / cable.elements = " +
              FormatNumber(element) + " m, time.step = " + FormatNumber(step) + " s)");
  }
  w.max_acceleration = map.Number("max_acceleration", Range::Above(0.0));
  w.brake_tension = map.Number("brake_tension", Range::Above(0.0), w.brake_tension);
  if (start.end.kind == core::EndKind::kFree) {
    map.field().Fail(
        "the winch sits at the cable's start, so cable.start must be held (fixed, driven or a "
        "body)");
  }
  // the elements the drum pays out keep the initial element length; a run holds at most
  // max_length / (length / elements) + 2 of them (docs/winch.md)
  const double per_element = c.length / c.elements;
  if (w.max_length / per_element > 10000.0) {
    map.Get("max_length").Fail("needs more than 10000 elements of the initial length " +
                               FormatNumber(per_element) +
                               " m (cable.length / cable.elements); use fewer, longer elements");
  }
  return w;
}

}  // namespace

core::CableParams ReadCable(const Field& field, const Field& line_types,
                            const std::string& base_dir, const core::Model& model) {
  const MapReader cable(field, MapKind::kCable);
  core::CableParams c;

  // discretization, then the line type (line_type_reader.h)
  c.length = cable.Number("length", Range::Above(0.0));
  c.elements = cable.Integer("elements", Range::Closed(1, 10000));
  const LineTypeFields line_type = ReadLineType(cable, line_types, base_dir, &c);
  // loads: absent means all on
  if (cable.Has("loads")) c.loads = ReadLoads(cable.Get("loads"));
  if (cable.Has("initial")) {
    static const std::vector<core::InitialShape> kShapes = {
        core::InitialShape::kVertical, core::InitialShape::kStraight, core::InitialShape::kStatic};
    c.initial = kShapes[cable.Get("initial").Choice({"vertical", "straight", "static"})];
  }

  // ends, then the rules between them
  const EndInput start = ReadEnd(cable.Require("start"), model);
  const EndInput end = ReadEnd(cable.Require("end"), model);
  c.start = start.end;
  c.end = end.end;
  CheckEnds(start, end, model);
  CheckInitialShape(c, start, end, model);
  if (cable.Has("winch")) c.winch = ReadWinch(cable, c, start, model);
  CheckStaticStrain(c, model, line_type);

  // initial velocity: given, else that of a driven end or a vessel, else zero
  core::Vec3 velocity = core::Vec3::Zero();
  for (const core::CableEnd* e : {&c.start, &c.end}) {
    if (e->kind == core::EndKind::kDriven) velocity = e->velocity;
    if (e->kind == core::EndKind::kVessel) {
      velocity = core::VesselMotion(model.vessels[e->body], model.environment.waves)
                     .At(0.0)
                     .velocity;
    }
  }
  c.initial_velocity = cable.Vector("initial_velocity", velocity);
  return c;
}

}  // namespace towsim::scene::internal
