#include "core/seabed_contact.h"

#include <cmath>

#include "core/environment_field.h"

namespace towsim::core {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

ContactLoad SeabedContactLoad(const EnvironmentField& sea, double width, const Vec3& r,
                              const Vec3& v, const Vec3& a, bool jacobians) {
  ContactLoad out;
  const double d = sea.SeabedDepth(r.x(), r.y());
  // above the bed (z <= d) the penetration (z - d) |n_z| below is not positive: no contact,
  // known before the normal is computed
  if (!(r.z() > d)) return out;
  const Vec3 n = sea.SeabedNormal(r.x(), r.y());
  const double nz = std::abs(n.z());
  const double delta = (r.z() - d) * nz;
  if (!(delta > 0.0)) return out;
  out.active = true;
  const SeabedContact& c = sea.seabed_contact();
  // onset over kContactOnset: stiffness term k e(delta), e = delta^2 / (2 d0) below d0 and
  // delta - d0 / 2 beyond, damping scaled by s = min(delta / d0, 1)
  const double d0 = kContactOnset;
  const bool ramp = delta < d0;
  const double e = ramp ? 0.5 * delta * delta / d0 : delta - 0.5 * d0;
  const double de = ramp ? delta / d0 : 1.0;  // de/ddelta (= s)
  const double s = de, ds = ramp ? 1.0 / d0 : 0.0;
  // f_n = w (k e(delta) - c s(delta) v.n) n
  const double vn = v.dot(n);
  const double fn = width * (c.stiffness * e - c.damping * s * vn);
  out.f = fn * n;
  out.normal = std::abs(fn);
  // d delta / dr = |n_z| (e_z - grad d), grad d = (d_x, d_y, 0) = -(n_x, n_y) / n_z
  Vec3 ddelta(0.0, 0.0, nz);
  if (nz > 0.0) ddelta += Vec3(n.x(), n.y(), 0.0) * (nz / n.z());
  const double dfn_ddelta = width * (c.stiffness * de - c.damping * ds * vn);
  if (jacobians) {
    out.df_dr = dfn_ddelta * n * ddelta.transpose();
    out.df_dv = -(width * c.damping * s) * n * n.transpose();
  }
  const double mu = c.friction, mu_lateral = c.lateral_friction();
  if (mu <= 0.0 && mu_lateral <= 0.0) return out;
  // sliding velocity in the bed's plane, split along the cable's projected tangent
  const Mat3 p = Mat3::Identity() - n * n.transpose();
  const Vec3 vt = p * v;
  Vec3 ta = p * a;
  const double ta_norm = ta.norm();
  const double mu_a = mu, mu_l = mu_lateral;
  const double sgn = fn >= 0.0 ? 1.0 : -1.0;  // d|f_n| = sgn d f_n
  // isotropic when the two coefficients agree (or no tangent): f_t = -|f_n| mu g(|v_t|) v_t,
  // g(s) = tanh(s / v_s) / s (-> 1 / v_s at s = 0)
  auto g_and_dg = [](double s, double* dg_over_s) {
    const double x = s / kFrictionSlipSpeed;
    if (x < 1e-4) {
      // g = (1 - x^2 / 3) / v_s, dg/ds / s = -2 / (3 v_s^3)
      *dg_over_s = -2.0 / (3.0 * kFrictionSlipSpeed * kFrictionSlipSpeed * kFrictionSlipSpeed);
      return (1.0 - x * x / 3.0) / kFrictionSlipSpeed;
    }
    const double th = std::tanh(x);
    const double g = th / s;
    const double dg = ((1.0 - th * th) / kFrictionSlipSpeed - g) / s;  // dg/ds
    *dg_over_s = dg / s;
    return g;
  };
  Vec3 ft = Vec3::Zero();
  Mat3 dft_dvt = Mat3::Zero();  // d f_t / d v_t at fixed |f_n|, per |f_n|
  if (mu_a == mu_l || ta_norm == 0.0) {
    const double s = vt.norm();
    double dg_s;
    const double g = g_and_dg(s, &dg_s);
    ft = -mu * g * vt;
    dft_dvt = -mu * (g * Mat3::Identity() + dg_s * vt * vt.transpose());
  } else {
    ta /= ta_norm;
    const double va = vt.dot(ta);
    const Vec3 vl = vt - va * ta;
    const double th = std::tanh(va / kFrictionSlipSpeed);
    double dg_s;
    const double sl = vl.norm();
    const double g = g_and_dg(sl, &dg_s);
    ft = -(mu_a * th) * ta - (mu_l * g) * vl;
    const Mat3 pl = Mat3::Identity() - ta * ta.transpose();
    const Mat3 dgvl = g * Mat3::Identity() + dg_s * vl * vl.transpose();  // d(g v_l)/dv_l
    dft_dvt =
        -(mu_a * (1.0 - th * th) / kFrictionSlipSpeed) * ta * ta.transpose() - mu_l * dgvl * pl;
    if (jacobians) {
      // the split turns with the tangent: t_a = P a / |P a|, v_a = v_t.t_a, v_l = v_t - v_a t_a
      //   df_t/dt_a = -mu_a (tanh I + sech^2 / v_s t_a v_t^T) + mu_l dgvl (v_a I + t_a v_t^T)
      //   dt_a/da = (I - t_a t_a^T) P / |P a|
      const Mat3 dft_dta = -mu_a * (th * Mat3::Identity() +
                                    ((1.0 - th * th) / kFrictionSlipSpeed) * ta * vt.transpose()) +
                           mu_l * dgvl * (va * Mat3::Identity() + ta * vt.transpose());
      out.df_da = out.normal * dft_dta * pl * p / ta_norm;
    }
  }
  out.f += out.normal * ft;
  if (jacobians) {
    // d(|f_n| f_t)/dv = f_t d|f_n|/dv + |f_n| df_t/dv_t P; d|f_n|/dv = -sgn w c n^T,
    // d|f_n|/dr = sgn w k ddelta^T (the bed's normal and the tangent's direction held)
    out.df_dv += -(sgn * width * c.damping * s) * ft * n.transpose() + out.normal * dft_dvt * p;
    out.df_dr += (sgn * dfn_ddelta) * ft * ddelta.transpose();
  }
  return out;
}

}  // namespace towsim::core
