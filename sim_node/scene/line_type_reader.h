#pragma once
// A cable's line type (docs/scene_format.md "Line types"): its section (hydrodynamic diameter,
// mass per length, EA, EI, axial damping) and its hydrodynamics (drag law, added mass).
// `cable.line_type: NAME` names one: the scene's `line_types:` map first, then the library
// file NAME.yaml in line_types/ beside the scene or one folder up (config/line_types/ for the
// shipped scenes, P/share/towsim/line_types/ installed); a NAME with a '/' or ending in .yaml
// is a file relative to the scene's folder. A property given in `cable` itself overrides the
// type's (a pair such as axial_stiffness / youngs_modulus as a whole; added_mass per
// coefficient).

#include <string>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// the strain a line's weight may give it before the run at most (CheckStaticStrain)
inline constexpr double kMaxStaticStrain = 0.5;

// Where the properties were read, for the rules that come after (CheckStaticStrain).
struct LineTypeFields {
  Field stiffness;  // the key that gave EA: axial_stiffness or youngs_modulus
};

// Reads the line type of the map `cable` (its line_type and its own keys) into c: diameter,
// mass_per_length, axial_stiffness, bending_stiffness, axial_damping, drag, added_mass.
// `line_types` is the scene's map (absent: none); `base_dir` the scene's folder.
LineTypeFields ReadLineType(const MapReader& cable, const Field& line_types,
                            const std::string& base_dir, core::CableParams* c);

// The tension the scene's weights surely put in the cable, T_min = 1/2 |m - rho_w A| g L (each
// of two held ends carries at least half the weight in water) + the weight in water
// |m_b - rho_w V_b| g of each sphere hanging on it, must not stretch it by more than
// kMaxStaticStrain: T_min / EA <= 0.5 (no cable material stretches half its length; the run's
// strain watch reports beyond 20 %). Fails at `fields.stiffness` otherwise.
void CheckStaticStrain(const core::CableParams& c, const core::Model& model,
                       const LineTypeFields& fields);
// T_min of CheckStaticStrain [N]
double MinimumTension(const core::CableParams& c, const core::Model& model);

}  // namespace towsim::scene::internal
