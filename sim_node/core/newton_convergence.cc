#include "core/newton_convergence.h"

#include <algorithm>
#include <cmath>

#include "core/system.h"

namespace towsim::core {

double WetWeightScale(const Model& model) {
  const Environment& env = model.environment;
  double w = 0.0;
  for (const CableParams& c : model.cables)
    w += std::abs(c.mass_per_length - env.water_density * c.area()) * env.gravity * c.length;
  for (const SphereBody& b : model.spheres)
    w += std::abs(b.mass - env.water_density * b.volume) * env.gravity;
  return std::max(w, kMinForceScale);
}

double JointForceScale(const System& system, const Eigen::VectorXd& lambda, double weight_scale) {
  double f = weight_scale;
  for (int c = 0; c < system.num_cables(); ++c)
    for (int end = 0; end < 2; ++end)
      if (system.end_lambda_count(end, c) >= 3)
        f = std::max(f, lambda.segment<3>(system.EndLambda(end, c)).norm());
  return f;
}

double ForceResidualNorm(const System& system, const Eigen::VectorXd& residual, int* worst_row) {
  double norm = 0.0;
  int worst = 0;
  auto take = [&](int row, double value) {
    if (value > norm) {
      norm = value;
      worst = row;
    }
  };
  for (int b = 0; b < system.num_spheres(); ++b)
    for (int i = 0; i < 3; ++i) {
      const int row = system.SphereDof(b) + i;
      take(row, std::abs(residual[row]));
    }
  for (int c = 0; c < system.num_cables(); ++c) {
    const double inv_le = 1.0 / system.element_length(c);
    for (int node = 0; node < system.num_nodes(c); ++node) {
      const int o = system.CableDof(node, c);
      for (int i = 0; i < 3; ++i) take(o + i, std::abs(residual[o + i]));
      for (int i = 3; i < 6; ++i) take(o + i, std::abs(residual[o + i]) * inv_le);
    }
  }
  if (worst_row) *worst_row = worst;
  return norm;
}

}  // namespace towsim::core
