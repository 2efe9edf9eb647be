#include "core/newton_convergence.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/system.h"

namespace towsim::core {

double IncrementScale(const Model& model) {
  double l = 1.0;
  for (const CableParams& c : model.cables) l = std::max(l, c.length);
  return l;
}

double WetWeight(const Model& model) {
  const Environment& env = model.environment;
  double w = 0.0;
  for (const CableParams& c : model.cables)
    w += std::abs(c.mass_per_length - env.water_density * c.area()) * env.gravity * c.length;
  for (const SphereBody& b : model.spheres)
    w += std::abs(b.mass - env.water_density * b.volume) * env.gravity;
  return w;
}

double WetWeightScale(const Model& model) { return std::max(WetWeight(model), kMinForceScale); }

double JointForceScale(const System& system, const Eigen::VectorXd& lambda, double weight_scale) {
  double f = weight_scale;
  for (int c = 0; c < system.num_cables(); ++c)
    for (int end = 0; end < 2; ++end)
      if (system.end_lambda_count(end, c) >= 3)
        f = std::max(f, lambda.segment<3>(system.EndLambda(end, c)).norm());
  return f;
}

double ShortestElement(const System& system) {
  double shortest = std::numeric_limits<double>::infinity();
  for (int c = 0; c < system.num_cables(); ++c)
    shortest = std::min(shortest, system.element_length(c));
  return shortest;
}

double ForceResidualNorm(const System& system, const Eigen::VectorXd& residual, int* worst_row) {
  // the nodes of a cable are consecutive 6-blocks [r, r']: two strided 3 x n views
  using Rows = Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>, 0, Eigen::OuterStride<6>>;
  double norm = 0.0;
  for (int b = 0; b < system.num_spheres(); ++b)
    norm = std::max(norm, residual.segment<3>(system.SphereDof(b)).lpNorm<Eigen::Infinity>());
  for (int c = 0; c < system.num_cables(); ++c) {
    const int n = system.num_nodes(c);
    const double* first = residual.data() + system.CableDof(0, c);
    norm = std::max(norm, Rows(first, 3, n).cwiseAbs().maxCoeff());
    norm = std::max(norm, Rows(first + 3, 3, n).cwiseAbs().maxCoeff() / system.element_length(c));
  }
  if (!worst_row) return norm;
  // the row that attains it (for diagnostics only)
  *worst_row = 0;
  double best = -1.0;
  auto take = [&](int row, double value) {
    if (value > best) {
      best = value;
      *worst_row = row;
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
  return norm;
}

}  // namespace towsim::core
