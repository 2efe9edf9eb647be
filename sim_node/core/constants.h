#pragma once
// Mathematical constants, one definition each, for the core, the scene reader and the node
// (the controllers, which do not include the core, keep theirs in controllers/common/laws.h).

namespace towsim::core {

// pi to double precision (the same double as M_PI)
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace towsim::core
