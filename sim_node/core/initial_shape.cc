#include "core/initial_shape.h"

#include <algorithm>
#include <cmath>
#include <functional>

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

// the root of a function that increases from f(lo) < 0 to f(hi) > 0 on a log scale (bisection
// to a relative 1e-13: a first guess needs no more, and it cannot fail)
double LogBisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int it = 0; it < 200 && hi > lo * (1.0 + 1e-13); ++it) {
    const double mid = std::sqrt(lo * hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

// a point of a planar line shape: horizontal x, height y (up), unit tangent (tx, ty)
struct PlanePoint {
  double x, y, tx, ty;
};

}  // namespace

bool LayOutCatenary(const System& sys, int k, State* s) {
  const Model& m = sys.model();
  const CableParams& c = m.cables[k];
  if (c.start.kind == EndKind::kFree || c.end.kind == EndKind::kFree) return false;
  const Vec3 p0 = SupportAtStart(m, c, 0), p1 = SupportAtStart(m, c, 1);
  const Vec3 chord = p1 - p0;
  const int nodes = sys.num_nodes(k);
  const double L = c.length;
  auto set_node = [&](int i, const Vec3& r, const Vec3& dr) {
    s->q.segment<3>(sys.CableDof(i, k)) = r;
    s->q.segment<3>(sys.CableDof(i, k) + 3) = dr;
    s->v.segment<3>(sys.CableDof(i, k)) = c.initial_velocity;
  };
  if (chord.norm() >= L) {  // taut: straight, stretched
    for (int i = 0; i < nodes; ++i) {
      const double u = static_cast<double>(i) / (nodes - 1);
      set_node(i, p0 + u * chord, chord / L);
    }
    return true;
  }
  // the vertical plane of the chord: horizontal unit e_h, up = -z (NED)
  Vec3 e_h(chord.x(), chord.y(), 0.0);
  const double X = e_h.norm();
  if (X < 1e-6 * L) return false;
  e_h /= X;
  const double Y = -chord.z();  // height of the end above the start
  // catenary y = a (cosh((x - x0) / a) - cosh(x0 / a)) through (0, 0) and (X, Y) with arc
  // length L: 2 a sinh(X / (2 a)) = sqrt(L^2 - Y^2) fixes a, Y / L = tanh((X - 2 x0) / (2 a))
  // fixes the vertex x0; arc length from the start s = a (sinh((x - x0) / a) + sinh(x0 / a))
  const double d = std::sqrt(L * L - Y * Y);
  const double a = LogBisect([&](double a) { return d - 2.0 * a * std::sinh(X / (2.0 * a)); },
                             X / 1400.0, 1e6 * L);
  const double x0 = 0.5 * X - a * std::atanh(Y / L);
  std::function<PlanePoint(double)> shape = [&](double arc) {
    const double u = std::asinh(arc / a + std::sinh(-x0 / a));
    return PlanePoint{x0 + a * u, a * (std::cosh(u) - std::cosh(x0 / a)), 1.0 / std::cosh(u),
                      std::tanh(u)};
  };
  Vec3 origin = p0;
  bool reversed = false;  // the shape runs from the end to the start
  // below the seabed at the vertex: grounded from the deeper end A toward the other end F,
  // height h of F above A: L - L_s + a_g asinh(L_s / a_g) = X, L_s = sqrt(h^2 + 2 h a_g)
  const bool vertex_inside = x0 > 0.0 && x0 < X;
  const double y_vertex = a * (1.0 - std::cosh(x0 / a));
  if (sys.sea().has_seabed() && vertex_inside) {
    const Vec3 low = p0 + x0 * e_h - y_vertex * Vec3::UnitZ();
    const double h = std::abs(Y);
    if (low.z() > sys.sea().SeabedDepth(low.x(), low.y()) && L - h < X && h > 0.0) {
      auto suspended = [h](double ag) { return std::sqrt(h * h + 2.0 * h * ag); };
      const double ag = LogBisect(
          [&](double ag) {
            const double ls = suspended(ag);
            return L - ls + ag * std::asinh(ls / ag) - X;
          },
          1e-9 * L, 1e9 * L);
      const double grounded = std::max(0.0, L - suspended(ag));
      reversed = Y < 0.0;  // the end is deeper: it is the anchor
      origin = reversed ? p1 : p0;
      shape = [grounded, ag](double arc) {
        if (arc <= grounded) return PlanePoint{arc, 0.0, 1.0, 0.0};
        const double u = std::asinh((arc - grounded) / ag);
        return PlanePoint{grounded + ag * u, ag * (std::cosh(u) - 1.0), 1.0 / std::cosh(u),
                          std::tanh(u)};
      };
    }
  }
  const Vec3 e_x = reversed ? Vec3(-e_h) : e_h;
  for (int i = 0; i < nodes; ++i) {
    const double arc = L * static_cast<double>(i) / (nodes - 1);
    const PlanePoint p = shape(reversed ? L - arc : arc);
    const Vec3 r = origin + p.x * e_x - p.y * Vec3::UnitZ();
    const Vec3 t = p.tx * e_x - p.ty * Vec3::UnitZ();  // along the shape's arc length
    set_node(i, r, reversed ? Vec3(-t) : t);
  }
  return true;
}

namespace {

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
  // straight over a span shorter than the cable would compress every element (a cable cannot
  // hold that; released, it may settle folded): the catenary's sag instead
  if (c.initial == InitialShape::kStraight && end_known && span < c.length &&
      LayOutCatenary(sys, k, s))
    return;

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
