// The `cables:` form of a scene (docs/scene_format.md "Networks"): read into Model::cables in
// order (a winched cable first), and every rule of the graph broken once, each with the key,
// the value and the rule in the message.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_loader.h"

namespace towsim::scene {
namespace {

const std::string kHead =
    "name: net\n"
    "time: {step: 0.05, duration: 1, output_rate: 10}\n";

const std::string kBodies =
    "bodies:\n"
    "  depressor: {type: sphere, mass: 500, volume: 0.06, position: [-100, 0, 100]}\n"
    "  fish: {type: sphere, mass: 400, volume: 0.39, position: [-150, 0, 110]}\n";

// a cable between start and end, `more` its further keys (its initial shape: straight unless
// given)
std::string Cable(const std::string& start, const std::string& end, const std::string& more = "") {
  const std::string initial =
      more.find("initial:") == std::string::npos ? ", initial: straight" : "";
  return "{length: 150, elements: 5, diameter: 0.03, density: 1300, youngs_modulus: 1.0e9, "
         "start: " + start + ", end: " + end + initial + more + "}";
}

const std::string kTow = "{driven: {position: [0, 0, 0], velocity: [2, 0, 0]}}";

std::string TwoPart(const std::string& main_more = "", const std::string& tether_more = "") {
  return kHead + kBodies + "cables:\n  main: " + Cable(kTow, "{body: depressor}", main_more) +
         "\n  tether: " + Cable("{body: depressor}", "{body: fish}", tether_more) + "\n";
}

std::string Error(const std::string& yaml) {
  try {
    LoadSceneFromString(yaml, "net.yaml", ".");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(NetworkReader, ReadsTheCablesInOrder) {
  const core::Model m = LoadSceneFromString(TwoPart(), "net.yaml", ".");
  ASSERT_EQ(m.cables.size(), 2u);
  EXPECT_EQ(m.cables[0].name, "main");
  EXPECT_EQ(m.cables[1].name, "tether");
  EXPECT_EQ(m.cables[1].start.kind, core::EndKind::kSphere);
  EXPECT_EQ(m.cables[1].start.body, 0);
  EXPECT_EQ(m.cables[1].end.body, 1);
  EXPECT_TRUE(SceneWarnings(m).empty());
  // the one-cable form is a cable named `cable`
  const core::Model one = LoadSceneFromString(
      kHead + kBodies + "cable: " + Cable(kTow, "{body: depressor}") + "\n", "one.yaml", ".");
  ASSERT_EQ(one.cables.size(), 1u);
  EXPECT_EQ(one.cables[0].name, "cable");
  // the fish is held by no cable in the one-cable scene: a warning, not an error
  const std::vector<std::string> w = SceneWarnings(one);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "bodies.fish: no cable end holds this body; it moves on its own");
}

TEST(NetworkReader, PutsTheWinchedCableFirst) {
  const core::Model m = LoadSceneFromString(
      TwoPart("", ", winch: {min_length: 50, max_length: 150, max_speed: 1, max_acceleration: 0.5}") , "net.yaml", ".");
  ASSERT_EQ(m.cables.size(), 2u);
  EXPECT_EQ(m.cables[0].name, "tether");
  EXPECT_TRUE(m.cables[0].winch.has_value());
}

TEST(NetworkReader, RejectsBrokenNetworks) {
  // cable and cables at once
  EXPECT_NE(Error(TwoPart() + "cable: " + Cable(kTow, "{body: fish}") + "\n")
                .find("give either cable (one cable) or cables (a network of named cables), "
                      "not both"),
            std::string::npos);
  // a name that a file or topic of every run takes, and a body's name
  const std::string reserved = kHead + kBodies + "cables:\n  forces: " +
                               Cable(kTow, "{body: fish}") + "\n";
  EXPECT_NE(Error(reserved).find("cables.forces"), std::string::npos);
  EXPECT_NE(Error(reserved).find("is taken by a file or topic of every run"), std::string::npos);
  const std::string body_name =
      kHead + kBodies + "cables:\n  fish: " + Cable(kTow, "{body: depressor}") + "\n";
  EXPECT_NE(Error(body_name).find("cable name fish is also a body's name"), std::string::npos);
  // an invalid name
  EXPECT_NE(Error(kHead + kBodies + "cables:\n  2main: " + Cable(kTow, "{body: fish}") + "\n")
                .find("cable names must match [A-Za-z_][A-Za-z0-9_]*"),
            std::string::npos);
  // nothing holds the tether and the fish (a heavy sphere): the part is named
  const std::string unheld = kHead + kBodies +
                             "cables:\n  main: " + Cable(kTow, "{free: true}", ", initial: vertical") +
                             "\n  tether: " + Cable("{body: depressor}", "{body: fish}") + "\n";
  EXPECT_NE(Error(unheld).find("nothing holds cables.tether, bodies.depressor and bodies.fish"),
            std::string::npos)
      << Error(unheld);
  // ... but a buoyant sphere holds its part (a float)
  std::string floating = unheld;
  floating.replace(floating.find("mass: 500, volume: 0.06"), 23, "mass: 100, volume: 2.0");
  EXPECT_EQ(Error(floating), "no error");
  // a massless sphere held by one cable end only
  std::string junction = kHead + kBodies +
                         "  knot: {type: sphere, mass: 0, volume: 0, position: [0, 0, 100]}\n"
                         "cables:\n  main: " + Cable(kTow, "{body: knot}") + "\n";
  EXPECT_NE(Error(junction).find("bodies.knot.mass = 0"), std::string::npos) << Error(junction);
  EXPECT_NE(Error(junction).find("a sphere without mass is a junction of cables: hold it by two "
                                 "or more cable ends (1 holds it), or give it a mass"),
            std::string::npos);
  // two winches
  EXPECT_NE(Error(TwoPart(", winch: {min_length: 50, max_length: 150, max_speed: 1, max_acceleration: 0.5}",
                          ", winch: {min_length: 50, max_length: 150, max_speed: 1, max_acceleration: 0.5}"))
                .find("this version runs one winch per scene"),
            std::string::npos);
  // a static start on one cable only
  EXPECT_NE(Error(TwoPart(", initial: static, initial_velocity: [2, 0, 0]"))
                .find("must be initial: static like cables.main: the static solve finds the "
                      "whole network's equilibrium"),
            std::string::npos)
      << Error(TwoPart(", initial: static, initial_velocity: [2, 0, 0]"));
  // ... and with two velocities
  EXPECT_NE(Error(TwoPart(", initial: static, initial_velocity: [2, 0, 0]",
                          ", initial: static, initial_velocity: [1, 0, 0]"))
                .find("initial_velocity must equal cables.main's"),
            std::string::npos)
      << Error(TwoPart(", initial: static, initial_velocity: [2, 0, 0]",
                       ", initial: static, initial_velocity: [1, 0, 0]"));
  // an empty map
  EXPECT_NE(Error(kHead + kBodies + "cables: {}\n").find("must name at least one cable"),
            std::string::npos);
}

}  // namespace
}  // namespace towsim::scene
