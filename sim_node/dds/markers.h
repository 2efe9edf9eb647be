#pragma once
// The 3D scene as a visualization_msgs/MarkerArray (ROS 2 Jazzy layout; docs/frames.md):
//
//   ns "cable"        id 0   LINE_STRIP in `world` (ENU): the cable nodes, each point coloured
//                            by its tension on the legend TensionColor (0 N blue ...
//                            kTensionLegendMax red); line width kCableLineWidth
//   ns "hull"         id b   per body, in frame <b> (FLU): a vehicle as a cylinder of its
//                            length and diameter along x about the body origin; a sphere body
//                            as the sphere of its volume
//   ns "fins"         id k   per lifting surface of every vehicle (numbered on), in <b>: a
//                            plate of span sqrt(S AR), chord S / span, thickness kFinThickness
//                            at its centre of pressure, its normal along the plate's thin axis
//   ns "cable_force"  id e   per held cable end (0 start, 1 end), in `world`: an arrow from
//                            the end node along the force the cable exerts on its support,
//                            kForceArrowScale metres per newton
//
// Markers in body frames are frame_locked (they follow the body's tf). Every marker is stamped
// with the simulation time. Pure translator: no DDS entities, no clocks; no allocation after
// construction.

#include <string>
#include <vector>

#include "core/simulation.h"
#include "dds/messages.h"

namespace towsim::dds {

inline constexpr double kTensionLegendMax = 5000.0;  // red at and above [N]
inline constexpr double kCableLineWidth = 0.25;      // drawn width of the cable [m]
inline constexpr double kFinThickness = 0.03;        // drawn thickness of a fin [m]
inline constexpr double kForceArrowScale = 1.0e-3;   // arrow length per force [m/N]

// the legend: t / kTensionLegendMax clamped to [0, 1] from blue (0, 0, 1) through green
// (0, 1, 0) at 0.5 to red (1, 0, 0); a negative tension (compression) is drawn blue
ColorMsg TensionColor(double tension);

class SceneMarkers {
 public:
  // the markers of sim's scene, sized once
  explicit SceneMarkers(const core::Simulation& sim);
  SceneMarkers(const SceneMarkers&) = delete;
  SceneMarkers& operator=(const SceneMarkers&) = delete;

  // cable points and colours, force arrows and stamps from sim's state
  void Update(const core::Simulation& sim);

  MarkerArrayMsg msg;
  int cable_marker() const { return 0; }  // index of the cable in msg.markers

 private:
  MarkerMsg& Add(const std::string& ns, int id, int type, const std::string& frame);

  std::vector<std::string> strings_;  // namespaces and frames the markers point to
  std::vector<MarkerMsg> markers_;
  std::vector<geometry_msgs_msg_dds__Point_> cable_points_;
  std::vector<ColorMsg> cable_colors_;
  // force arrows: marker index, cable end (0 start: node 0, 1 end: the last node in use); two
  // points each
  struct Arrow {
    size_t marker;
    int end;
  };
  std::vector<Arrow> arrows_;
  std::vector<geometry_msgs_msg_dds__Point_> arrow_points_;
};

}  // namespace towsim::dds
