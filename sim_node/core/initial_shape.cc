#include "core/initial_shape.h"

#include <cmath>

#include "core/vessel_motion.h"

namespace towsim::core {
namespace {

// start (end = 0) or end support position at t = 0, using the spheres' and vehicles' initial
// positions and the vessels' poses at t = 0
Vec3 SupportAtStart(const Model& m, const CableParams& c, int end) {
  const CableEnd& e = end == 0 ? c.start : c.end;
  if (e.kind == EndKind::kSphere) return m.spheres[e.body].position + e.at_B;
  if (e.kind == EndKind::kVehicle) {
    const Vehicle& v = m.vehicles[e.body];
    return v.position + QuaternionFromEulerZYX(v.euler) * e.at_B;
  }
  if (e.kind == EndKind::kVessel)
    return VesselMotion(m.vessels[e.body], m.environment.waves).At(0.0).PointAt(e.at_B);
  return e.position;
}

// cable k's nodes: its shape (cable.initial) from its start support
void ShapeCable(const System& sys, int k, State* s) {
  const Model& m = sys.model();
  const CableParams& c = m.cables[k];
  const int nodes = sys.num_nodes(k);
  const Vec3 p0 = SupportAtStart(m, c, 0);
  const bool end_known = c.end.kind != EndKind::kFree;
  const Vec3 p1 = end_known ? SupportAtStart(m, c, 1) : p0 + c.length * Vec3::UnitZ();
  const Vec3 chord = p1 - p0;
  const double span = chord.norm();

  // shape r(u), u = x / L in [0, 1], and dr/dx
  Vec3 sag_dir = Vec3::Zero();
  double sag = 0.0;
  bool vertical = c.initial == InitialShape::kVertical || !end_known;
  if (c.initial == InitialShape::kStatic && end_known && span < c.length) {
    // parabola with arc length ~ L: L = span + 8 sag^2 / (3 span)
    const Vec3 g = Vec3::UnitZ();
    const Vec3 t = span > 0.0 ? Vec3(chord / span) : Vec3::UnitX();
    sag_dir = g - g.dot(t) * t;
    if (sag_dir.norm() < 1e-6) sag_dir = Vec3::UnitX() - Vec3::UnitX().dot(t) * t;
    sag_dir.normalize();
    sag = std::sqrt(3.0 * std::max(span, 1e-3 * c.length) * (c.length - span) / 8.0);
  }
  for (int i = 0; i < nodes; ++i) {
    const double u = static_cast<double>(i) / (nodes - 1);
    Vec3 r, dr;
    if (vertical) {
      r = p0 + (u * c.length) * Vec3::UnitZ();
      dr = Vec3::UnitZ();
    } else {
      r = p0 + u * chord + (4.0 * sag * u * (1.0 - u)) * sag_dir;
      dr = (chord + (4.0 * sag * (1.0 - 2.0 * u)) * sag_dir) / c.length;
    }
    s->q.segment<3>(sys.CableDof(i, k)) = r;
    s->q.segment<3>(sys.CableDof(i, k) + 3) = dr;
    s->v.segment<3>(sys.CableDof(i, k)) = c.initial_velocity;
  }
}

}  // namespace

void BuildInitialState(const System& sys, State* s) {
  const Model& m = sys.model();
  const int n = sys.num_q();
  s->t = 0.0;
  s->q.setZero(n);
  s->v.setZero(n);
  s->a.setZero(n);
  s->a_alpha.setZero(n);
  s->lambda.setZero(sys.num_lambda());
  s->supports.assign(sys.num_ends(), SupportMotion());
  for (int b = 0; b < sys.num_spheres(); ++b) {
    s->q.segment<3>(sys.SphereDof(b)) = m.spheres[b].position;
    s->v.segment<3>(sys.SphereDof(b)) = m.spheres[b].velocity;
  }
  s->vehicles.clear();
  for (const Vehicle& v : m.vehicles) {
    VehicleState vs;
    vs.p_W = v.position;
    vs.q_WB = QuaternionFromEulerZYX(v.euler);
    vs.nu = v.nu;
    // actuators start at rest (no thrust, fins centred) and follow the commands from t = 0
    s->vehicles.push_back(vs);
  }

  for (int k = 0; k < sys.num_cables(); ++k) ShapeCable(sys, k, s);
}

}  // namespace towsim::core
