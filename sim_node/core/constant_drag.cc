#include "core/cable_drag.h"

namespace towsim::core {

// the constant coefficients' instantiation (cable_drag.h says why in a file of its own)
template DragResult CableDragOf<true>(const FluidProperties&, const CableDragLaw&, double,
                                      const Eigen::Vector3d&, const Eigen::Vector3d&, bool);

}  // namespace towsim::core
