#include "app/foxglove/foxglove_layout.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/constants.h"
#include "dds/translators.h"

namespace towsim::app {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kTeleopRudderDeg = 20.0;  // the Teleop panel's left / right rudder [deg]
constexpr double kGridMin = 500.0;         // the smallest grid [m], 10 m cells
constexpr double kFarMin = 5000.0;         // the smallest far clipping plane [m]

// an integral value as a JSON integer (4165, not 4165.0), else the value to 3 decimals
Json Number(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return static_cast<long long>(v);
  return std::round(v * 1000.0) / 1000.0;
}

double RoundUp(double v, double step) { return std::ceil(v / step) * step; }

// "tow_vehicle" -> "tow vehicle"
std::string Label(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

// the ROS 2 name of a topic of the node
std::string Ros(const wire::TopicNames& names, wire::Topic topic, const std::string& owner = "") {
  return wire::RosTopicName(names.Name(topic, owner));
}

// the bodies as the node numbers them (core/simulation.h body_name): spheres, vehicles, vessels
std::vector<std::string> BodyNames(const core::Model& model) {
  std::vector<std::string> all;
  for (const core::SphereBody& s : model.spheres) all.push_back(s.name);
  for (const core::Vehicle& v : model.vehicles) all.push_back(v.name);
  for (const core::Vessel& v : model.vessels) all.push_back(v.name);
  return all;
}

Json PlotPath(const std::string& value, const std::string& label) {
  return Json{{"value", value},
              {"enabled", true},
              {"timestampMethod", "headerStamp"},
              {"label", label}};
}

Json Plot(const std::string& title, Json paths) {
  return Json{{"title", title},
              {"paths", std::move(paths)},
              {"showXAxisLabels", true},
              {"showYAxisLabels", true},
              {"showLegend", true},
              {"legendDisplay", "floating"},
              {"showPlotValuesInLegend", true},
              {"isSynced", true},
              {"xAxisVal", "timestamp"},
              {"sidebarDimension", 240}};
}

Json ThreeD(const core::Model& model, const wire::TopicNames& names) {
  std::string follow = "world";  // docs/frames.md: the root of the tf tree
  if (!model.vehicles.empty()) {
    follow = model.vehicles.front().name;
  } else if (const std::vector<std::string> bodies = BodyNames(model); !bodies.empty()) {
    follow = bodies.front();
  }
  const double distance = CameraDistance(model);
  const double reach = SystemReach(model);
  const double grid = std::max(kGridMin, RoundUp(2.0 * reach, 100.0));
  const double far = std::max(kFarMin, RoundUp(2.0 * (distance + reach), 1000.0));
  Json topics = Json::object();
  for (wire::Topic t : {wire::Topic::kMarkers, wire::Topic::kTf, wire::Topic::kTfStatic}) {
    topics[Ros(names, t)] = Json{{"visible", true}};
  }
  return Json{
      {"cameraState",
       {{"perspective", true},
        {"distance", Number(distance)},
        {"phi", 70},
        {"thetaOffset", 30},
        {"targetOffset", {0, 0, 0}},
        {"target", {0, 0, 0}},
        {"targetOrientation", {0, 0, 0, 1}},
        {"fovy", Number(kLayoutFovyDeg)},
        {"near", 0.5},
        {"far", Number(far)}}},
      {"followMode", "follow-position"},
      {"followTf", follow},
      {"scene",
       {{"enableStats", false},
        {"transforms", {{"showLabel", false}, {"axisScale", 3}, {"lineWidth", 1}}}}},
      {"transforms",
       {{"frame:world", {{"visible", false}}}, {"frame:world_ned", {{"visible", false}}}}},
      {"topics", topics},
      {"layers",
       {{"grid",
         {{"visible", true},
          {"frameId", "world"},
          {"size", Number(grid)},
          {"divisions", Number(grid / 10.0)},
          {"lineWidth", 1},
          {"color", "#248effff"},
          {"position", {0, 0, 0}},
          {"rotation", {0, 0, 0}},
          {"layerId", "foxglove.Grid"}}}}},
      // what the panel's publish tool advertises (docs/foxglove.md: accepted and ignored)
      {"publish",
       {{"type", "point"},
        {"poseTopic", "/move_base_simple/goal"},
        {"pointTopic", "/clicked_point"},
        {"poseEstimateTopic", "/initialpose"}}},
      {"imageMode", Json::object()}};
}

Json TensionPlot(const core::Model& model, const wire::TopicNames& names) {
  const bool one = model.cables.size() == 1;
  Json paths = Json::array();
  std::string counts;
  for (const core::CableParams& c : model.cables) {
    const std::string topic = Ros(names, wire::Topic::kCableState, c.name) + ".tensions";
    // the bottom node: index E of the E + 1 nodes; a winched cable's last node, whatever
    // the drum has paid out (docs/winch.md)
    const std::string bottom = c.winch ? "[-1]" : "[" + std::to_string(c.elements) + "]";
    const std::string prefix = one ? "" : Label(c.name) + " ";
    paths.push_back(PlotPath(topic + "[0]", prefix + "top"));
    paths.push_back(PlotPath(topic + bottom, prefix + "bottom"));
    const std::string count = c.winch ? "winched, the last node"
                                      : std::to_string(c.elements) + " elements";
    counts += (counts.empty() ? "" : ", ") + (one ? "" : Label(c.name) + ": ") + count;
  }
  return Plot(std::string(one ? "cable tension" : "cable tensions") +
                  " [N]: top node, bottom node (" + counts + ")",
              std::move(paths));
}

// the first vehicle that takes commands (the node's command readers: dds::IsCommandable), or
// nullptr
const core::Vehicle* FirstCommanded(const core::Model& model) {
  for (const core::Vehicle& v : model.vehicles) {
    if (dds::IsCommandable(v.params)) return &v;
  }
  return nullptr;
}

Json Teleop(const core::Model& model, const core::Vehicle& v, const wire::TopicNames& names) {
  double thrust = 0.0;
  for (const core::ScriptEntry& e : model.script) {
    if (e.set_thrust && e.body == v.name) thrust = std::max(thrust, e.thrust);
  }
  if (!(thrust > 0.0)) thrust = v.params.max_thrust;
  const double rudder =
      std::min(kTeleopRudderDeg * core::kPi / 180.0, v.params.rudder.max_deflection);
  return Json{{"topic", Ros(names, wire::Topic::kCommand, v.name)},
              {"publishRate", 2},
              {"upButton", {{"field", "linear-x"}, {"value", Number(thrust)}}},
              {"downButton", {{"field", "linear-x"}, {"value", 0}}},
              {"leftButton", {{"field", "angular-z"}, {"value", Number(rudder)}}},
              {"rightButton", {{"field", "angular-z"}, {"value", Number(-rudder)}}}};
}

// panels one above the other, each taking an equal share
Json Column(const std::vector<std::string>& ids) {
  if (ids.size() == 1) return ids.front();
  const std::vector<std::string> rest(ids.begin() + 1, ids.end());
  return Json{{"direction", "column"},
              {"first", ids.front()},
              {"second", Column(rest)},
              {"splitPercentage", Number(std::round(100.0 / static_cast<double>(ids.size())))}};
}

}  // namespace

double SystemReach(const core::Model& model) {
  double reach = 0.0;
  for (const core::CableParams& c : model.cables) reach += c.winch ? c.winch->max_length : c.length;
  return reach;
}

double CameraDistance(const core::Model& model) {
  const double half_fovy = 0.5 * kLayoutFovyDeg * core::kPi / 180.0;
  return RoundUp(SystemReach(model) / std::sin(half_fovy), 10.0);
}

std::string FoxgloveLayoutJson(const core::Model& model, const wire::TopicNames& names) {
  Json config = Json::object();
  config["3D!towsim"] = ThreeD(model, names);
  std::vector<std::string> right;  // the panels right of the 3D panel

  const std::vector<std::string> bodies = BodyNames(model);
  if (!bodies.empty()) {
    Json depth = Json::array();
    for (const std::string& b : bodies) {
      depth.push_back(PlotPath(Ros(names, wire::Topic::kOdom, b) + ".pose.pose.position.z",
                               Label(b) + " z"));
    }
    config["Plot!depth"] = Plot("depth [m] (world_ned z)", std::move(depth));
    right.push_back("Plot!depth");
  }
  config["Plot!tension"] = TensionPlot(model, names);
  right.push_back("Plot!tension");

  Json speed = Json::array();
  for (const core::Vehicle& v : model.vehicles) {
    speed.push_back(
        PlotPath(Ros(names, wire::Topic::kOdom, v.name) + ".twist.twist.linear.x", Label(v.name)));
  }
  for (const core::Vessel& v : model.vessels) {
    speed.push_back(
        PlotPath(Ros(names, wire::Topic::kOdom, v.name) + ".twist.twist.linear.x", Label(v.name)));
  }
  if (!speed.empty()) {
    config["Plot!speed"] = Plot("surge speed u [m/s]", std::move(speed));
    right.push_back("Plot!speed");
  }
  if (const core::Vehicle* v = FirstCommanded(model)) {
    const std::string id = "Teleop!" + v->name;
    config[id] = Teleop(model, *v, names);
    right.push_back(id);
  }

  // the 3D panel on the left, the plots and the Teleop on the right: two columns of two when
  // there are four (the plots above, speed and Teleop below), else one column
  Json side;
  if (right.size() == 4) {
    side = Json{{"direction", "column"},
                {"first",
                 {{"direction", "column"},
                  {"first", right[0]},
                  {"second", right[1]},
                  {"splitPercentage", 50}}},
                {"second",
                 {{"direction", "column"},
                  {"first", right[2]},
                  {"second", right[3]},
                  {"splitPercentage", 55}}},
                {"splitPercentage", 55}};
  } else {
    side = Column(right);
  }
  const Json layout{{"configById", config},
                    {"globalVariables", Json::object()},
                    {"userNodes", Json::object()},
                    {"playbackConfig", {{"speed", 1}}},
                    {"layout",
                     {{"direction", "row"},
                      {"first", "3D!towsim"},
                      {"second", side},
                      {"splitPercentage", 60}}}};
  return layout.dump(2) + "\n";
}

}  // namespace towsim::app
