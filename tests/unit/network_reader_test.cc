// The `cables:` form of a scene (docs/scene_format.md "Networks"): read into Model::cables in
// order (the winched cables first), and every rule of the graph broken once, each with the key,
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

// a winch's keys, `name` its further keys ("name: aft, ")
std::string Winch(const std::string& name = "") {
  return ", winch: {" + name + "min_length: 50, max_length: 150, max_speed: 1, "
         "max_acceleration: 0.5}";
}

TEST(NetworkReader, NamesSeveralWinchesAndPutsTheirCablesFirst) {
  // one winch: named winch (its topic rt/<ns>/winch/command and winch.csv, as in a one-cable
  // scene)
  EXPECT_EQ(LoadSceneFromString(TwoPart(Winch()), "net.yaml", ".").cables[0].winch->name,
            "winch");
  // two: each after its cable, or its name:; the winched cables first, in the scene's order
  core::Model m = LoadSceneFromString(TwoPart(Winch(), Winch()), "net.yaml", ".");
  ASSERT_EQ(m.cables.size(), 2u);
  EXPECT_EQ(m.cables[0].winch->name, "main_winch");
  EXPECT_EQ(m.cables[1].winch->name, "tether_winch");
  m = LoadSceneFromString(TwoPart(Winch("name: deck, "), Winch()), "net.yaml", ".");
  EXPECT_EQ(m.cables[0].winch->name, "deck");
  // the cables without a winch go after those with one
  m = LoadSceneFromString(TwoPart("", Winch()) + "  spare: " +
                              Cable("{fixed: [0, 5, 0]}", "{fixed: [0, 5, 150]}", Winch()) + "\n",
                          "net.yaml", ".");
  ASSERT_EQ(m.cables.size(), 3u);
  EXPECT_EQ(m.cables[0].name, "tether");
  EXPECT_EQ(m.cables[1].name, "spare");
  EXPECT_EQ(m.cables[2].name, "main");
  EXPECT_EQ(m.cables[1].winch->name, "spare_winch");
  // script entries name their winch; with one winch they may leave it out
  m = LoadSceneFromString(TwoPart(Winch(), Winch()) +
                              "script:\n  - {at: 1, winch: tether_winch, winch_speed: -0.5}\n"
                              "  - {at: 2, winch: main_winch, winch_length: 120}\n",
                          "net.yaml", ".");
  ASSERT_EQ(m.script.size(), 2u);
  EXPECT_EQ(m.script[0].winch_index, 1);
  EXPECT_EQ(m.script[1].winch_index, 0);
  m = LoadSceneFromString(TwoPart("", Winch()) + "script:\n  - {at: 1, winch_speed: 0.5}\n",
                          "net.yaml", ".");
  EXPECT_EQ(m.script[0].winch_index, 0);
}

TEST(NetworkReader, RejectsBadWinchNamesAndScriptEntries) {
  const std::string two = TwoPart(Winch(), Winch());
  // the same name twice, a cable's, a body's, a file's or topic's, and "winch" among several
  EXPECT_NE(Error(TwoPart(Winch("name: aft, "), Winch("name: aft, ")))
                .find("cables.tether.winch.name = aft (net.yaml:8): winch name aft is taken by "
                      "another winch: each winch has its own name"),
            std::string::npos)
      << Error(TwoPart(Winch("name: aft, "), Winch("name: aft, ")));
  EXPECT_NE(Error(TwoPart(Winch("name: tether, ")))
                .find("cables.main.winch.name = tether (net.yaml:7): winch name tether is also a "
                      "cable's name: winches, cables and bodies share one namespace (topics, "
                      "files)"),
            std::string::npos);
  EXPECT_NE(Error(TwoPart(Winch("name: fish, "), Winch()))
                .find("cables.main.winch.name = fish (net.yaml:7): winch name fish is also a "
                      "body's name: winches, cables and bodies share one namespace (topics, "
                      "files)"),
            std::string::npos);
  EXPECT_NE(Error(TwoPart(Winch("name: status, ")))
                .find("cables.main.winch.name = status (net.yaml:7): winch name status is taken "
                      "by a file or topic of every run"),
            std::string::npos);
  EXPECT_NE(Error(TwoPart(Winch("name: winch, "), Winch()))
                .find("cables.main.winch.name = winch (net.yaml:7): winch name winch is the one "
                      "winch's of a scene (winch.csv, rt/<ns>/winch/command); with 2 winches "
                      "name them otherwise"),
            std::string::npos);
  // a default name taken: cable main's winch would be main_winch, a body's name
  EXPECT_NE(Error(kHead + kBodies + "  main_winch: {type: sphere, mass: 1, volume: 0.01, "
                  "position: [0, 9, 1]}\n" + "cables:\n  main: " +
                  Cable(kTow, "{body: depressor}", Winch()) + "\n  tether: " +
                  Cable("{body: depressor}", "{body: fish}", Winch()) + "\n")
                .find("winch name (cable name + _winch) main_winch is also a body's name"),
            std::string::npos);
  // the winch sits at its cable's start: a free start cannot hold a drum
  const std::string free_start =
      Error(kHead + kBodies + "cables:\n  main: " +
            Cable(kTow, "{body: depressor}", ", initial: static" + Winch()) + "\n  tether: " +
            Cable("{free: true}", "{body: depressor}", ", initial: static" + Winch()) + "\n");
  EXPECT_NE(free_start.find("the winch sits at the cable's start, so cable.start must be held (fixed, "
                      "driven or a body)"),
            std::string::npos)
      << free_start;
  // script entries: the winch by name, needed with several, known, and with a command
  EXPECT_NE(Error(two + "script:\n  - {at: 1, winch_speed: 0.5}\n")
                .find("script[0].winch_speed = 0.5 (net.yaml:10): needs winch: <name>, the scene "
                      "has 2 winches (main_winch, tether_winch)"),
            std::string::npos)
      << Error(two + "script:\n  - {at: 1, winch_speed: 0.5}\n");
  EXPECT_NE(Error(two + "script:\n  - {at: 1, winch: bow, winch_speed: 0.5}\n")
                .find("script[0].winch = bow (net.yaml:10): no such winch (winches: main_winch, "
                      "tether_winch)"),
            std::string::npos);
  EXPECT_NE(Error(two + "script:\n  - {at: 1, winch: main_winch}\n")
                .find("script[0].winch = main_winch (net.yaml:10): names the winch of a "
                      "winch_speed or winch_length; give one"),
            std::string::npos);
  EXPECT_NE(Error(two + "script:\n  - {at: 1, winch: tether_winch, winch_speed: 2}\n")
                .find("script[0].winch_speed = 2 (net.yaml:10): must be within "
                      "+-cables.tether.winch.max_speed = 1"),
            std::string::npos);
  // the one-cable form's winch is `winch`
  const std::string one_cable =
      Error(kHead + kBodies + "cable: " + Cable(kTow, "{body: depressor}", Winch("name: aft, ")) +
            "\n");
  EXPECT_NE(one_cable.find("cable.winch.name = aft (net.yaml:6): the winch of the one-cable form is "
                      "named winch (rt/<ns>/winch/command, winch.csv); name: applies to the "
                      "winches of cables:"),
            std::string::npos)
      << one_cable;
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
