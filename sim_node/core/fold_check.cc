#include "core/fold_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/system.h"

namespace towsim::core {

FoldReport FindFold(const System& sys, const Eigen::VectorXd& q) {
  FoldReport out;
  for (int c = 0; c < sys.num_cables(); ++c) {
    const int elements = sys.NumElements(c);
    for (int e = 0; e < elements; ++e) {
      const int o = sys.CableDof(e, c);
      const Vec3 ra = q.segment<3>(o), da = q.segment<3>(o + 3);
      const Vec3 rb = q.segment<3>(o + 6), db = q.segment<3>(o + 9);
      const Vec3 chord = rb - ra;
      // the middle slope times the rest length l: 3/2 c - l (r'_a + r'_b) / 4 (element 0 of
      // a winch's cable has the drum's rest length)
      const double l = sys.RestLength(e, c);
      const double len = chord.norm();
      const Vec3 dm = 1.5 * chord - 0.25 * l * (da + db);
      const double na = da.norm(), nb = db.norm();
      const double ca = da.dot(chord), cb = db.dot(chord), cm = dm.dot(chord);
      const double sa = na - 1.0, sb = nb - 1.0;
      const bool bad_strain = sa < -kFoldCompression || sb < -kFoldCompression ||
                              sa > kFoldStretch || sb > kFoldStretch;
      if (ca > 0.0 && cb > 0.0 && cm > 0.0 && !bad_strain) continue;
      out.folded = true;
      out.cable = c;
      out.element = e;
      out.strain = std::abs(sa) > std::abs(sb) ? sa : sb;
      const double scale = std::max(len, 1e-300);
      out.cosine = std::min({ca / (std::max(na, 1e-300) * scale),
                             cb / (std::max(nb, 1e-300) * scale),
                             cm / std::max(dm.norm() * scale, 1e-300)});
      return out;
    }
  }
  return out;
}

namespace {

double Angle(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

}  // namespace

double TotalTurning(const System& sys, const Eigen::VectorXd& q, int c) {
  double total = 0.0;
  for (int e = 0; e < sys.NumElements(c); ++e) {
    const int o = sys.CableDof(e, c);
    const double l = sys.RestLength(e, c);
    const Vec3 da = q.segment<3>(o + 3), db = q.segment<3>(o + 9);
    const Vec3 dm = 1.5 * (q.segment<3>(o + 6) - q.segment<3>(o)) - 0.25 * l * (da + db);
    total += Angle(da, dm) + Angle(dm, db);
  }
  return total;
}

std::string FoldReport::Describe(const System& sys) const {
  if (!folded) return {};
  char text[240];
  const char* why = cosine <= 0.0 ? "a slope turned against its chord"
                    : strain < 0.0 ? "compressed beyond what a cable carries"
                                   : "stretched beyond any cable material";
  std::snprintf(text, sizeof text,
                "cable '%s' element %d (nodes %d-%d) folded: %s (cos %.3g), strain %.4g",
                sys.model().cables[cable].name.c_str(), element, element, element + 1, why,
                cosine, strain);
  return text;
}

}  // namespace towsim::core
