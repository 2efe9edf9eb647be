#pragma once
// The 3D scene as a visualization_msgs/MarkerArray (ROS 2 Jazzy layout; docs/frames.md):
//
//   ns "cable"        id c   per cable c (the scene's order; the one cable: id 0), LINE_STRIP
//                            in `world` (ENU): the cable's nodes, each point coloured by its
//                            tension on the legend TensionColor (0 N blue ...
//                            kTensionLegendMax red); line width kCableLineWidth
//   ns "hull"         id b   per body, in frame <b> (FLU): a vehicle as a cylinder of its
//                            length and diameter along x about the body origin; a sphere body
//                            as the sphere of its volume; a vessel as a box of
//                            kVesselMarkerSize whose keel is kVesselMarkerDraught below the
//                            origin (the scene gives a vessel no geometry)
//   ns "fins"         id k   per lifting surface of every vehicle (numbered on), in <b>: a
//                            plate of span sqrt(S AR), chord S / span, thickness kFinThickness
//                            at its centre of pressure, its normal along the plate's thin axis
//   ns "cable_force"  id 2c+e  per held end e (0 start, 1 end) of cable c, in `world`: an
//                            arrow from the end node along the force the cable exerts on its
//                            support, kForceArrowScale metres per newton
//   ns "sea_surface"  id 0   scene with waves: TRIANGLE_LIST in `world_ned` (NED, as tf has it
//                            under `world`), a square patch of kSeaPatchCells x kSeaPatchCells
//                            cells of kSeaPatchCellSize metres around the tow vehicle (its centre
//                            on the nearest grid corner, so that the vertices stay on a fixed
//                            lattice as the vehicle moves); vertex (x, y, -eta(x, y, t)), eta the
//                            surface elevation (core/wave_field.h, positive up), two triangles
//                            per cell, each vertex coloured by SeaColor(eta)
//   ns "seabed"       id 0   scene with a seabed: the same patch at the seabed, vertex
//                            (x, y, d(x, y)), d the seabed depth (core/seabed.h: flat, plane or
//                            grid); one colour
//
// The tow vehicle: the first vehicle with a propeller, else the first vessel, else the first
// vehicle, else the patch follows the first cable's start node.

//
// Markers in order: the cables, hulls, fins, force arrows, sea surface, seabed.
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
// a vessel's drawn box (length, beam, height) [m] and its draught below the origin [m]
inline const Eigen::Vector3d kVesselMarkerSize(40.0, 10.0, 8.0);
inline constexpr double kVesselMarkerDraught = 4.0;
inline constexpr double kForceArrowScale = 1.0e-3;   // arrow length per force [m/N]
inline constexpr int kSeaPatchCells = 16;            // cells per side of the sea patches
inline constexpr double kSeaPatchCellSize = 12.5;    // [m]: a 200 m square

// the legend: t / kTensionLegendMax clamped to [0, 1] from blue (0, 0, 1) through green
// (0, 1, 0) at 0.5 to red (1, 0, 0); a negative tension (compression) is drawn blue
ColorMsg TensionColor(double tension);

// the sea's legend: s = eta / (2 eta_max) + 1/2 clamped to [0, 1], eta_max the sum of the wave
// amplitudes (no crest rises higher), from deep blue (0.0, 0.15, 0.45) in the deepest trough to
// pale blue (0.6, 0.85, 1.0) on the highest crest; alpha kSeaAlpha
inline constexpr float kSeaAlpha = 0.7f;
ColorMsg SeaColor(double eta, double eta_max);

class SceneMarkers {
 public:
  // the markers of sim's scene, sized once
  explicit SceneMarkers(const core::Simulation& sim);
  SceneMarkers(const SceneMarkers&) = delete;
  SceneMarkers& operator=(const SceneMarkers&) = delete;

  // cable points and colours, force arrows and stamps from sim's state
  void Update(const core::Simulation& sim);

  MarkerArrayMsg msg;
  int cable_marker(int c = 0) const { return c; }  // index of cable c in msg.markers

  // the body the sea patches follow (the tow vehicle); -1: the cable's start node
  int patch_body() const { return patch_body_; }

 private:
  MarkerMsg& Add(const std::string& ns, int id, int type, const std::string& frame);

  std::vector<std::string> strings_;  // namespaces and frames the markers point to
  std::vector<MarkerMsg> markers_;
  // per cable: its points and their colours
  std::vector<std::vector<geometry_msgs_msg_dds__Point_>> cable_points_;
  std::vector<std::vector<ColorMsg>> cable_colors_;
  // force arrows: marker index, cable, cable end (0 start: node 0, 1 end: the last node in
  // use); two points each, at arrow_points_[2 (2 cable + end)]
  struct Arrow {
    size_t marker;
    int cable;
    int end;
  };
  std::vector<Arrow> arrows_;
  std::vector<geometry_msgs_msg_dds__Point_> arrow_points_;
  // the sea patches: marker index (-1: none), vertices and the surface's colours
  void UpdatePatches(const core::Simulation& sim);
  long sea_marker_ = -1, seabed_marker_ = -1;
  int patch_body_ = -1;
  double eta_max_ = 0.0;  // sum of the wave amplitudes [m]
  std::vector<geometry_msgs_msg_dds__Point_> sea_points_, seabed_points_;
  std::vector<ColorMsg> sea_colors_;
  std::vector<double> corner_eta_, corner_depth_, wave_work_;  // at the (n + 1)^2 corners
};

}  // namespace towsim::dds
