#pragma once
// Test helper: a small cable network (docs/scene_format.md "Networks") for the tests of what
// the node sends per cable: a main cable of 30 m (4 elements) from a fixed point down to a
// depressor, and a tether of 10 m (3 elements) from 0.5 m below the depressor's centre down to
// a towfish, both spheres, hanging straight (initial: vertical).
//
//   main    fixed (0, 0, 0) -> depressor            5 nodes
//   tether  depressor at (0, 0, 0.5) -> towfish     4 nodes

#include <string>

#include "core/model.h"
#include "scene/scene_loader.h"

namespace towsim::test {

inline constexpr const char* kNetworkScene = R"(
name: network
time: {step: 0.05, duration: 1, output_rate: 10}
bodies:
  depressor: {type: sphere, mass: 300, volume: 0.05, position: [0, 0, 30]}
  towfish: {type: sphere, mass: 80, volume: 0.02, position: [0, 0, 40.5]}
cables:
  main: {length: 30, elements: 4, diameter: 0.03, density: 1300, youngs_modulus: 7.0e8,
         initial: vertical, start: {fixed: [0, 0, 0]}, end: {body: depressor}}
  tether: {length: 10, elements: 3, diameter: 0.02, density: 1100, youngs_modulus: 7.0e8,
           initial: vertical, start: {body: depressor, at: [0, 0, 0.5]},
           end: {body: towfish}}
)";

inline core::Model LoadNetwork() {
  return scene::LoadSceneFromString(kNetworkScene, "network.yaml",
                                    std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
}

}  // namespace towsim::test
