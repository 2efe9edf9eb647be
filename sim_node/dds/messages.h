#pragma once
// The generated C types of msgs/ (idlc): one include for the whole wire contract.

#include "builtin_interfaces.h"
#include "geometry_msgs.h"
#include "nav_msgs.h"
#include "rmw_dds_common.h"
#include "rosgraph_msgs.h"
#include "sensor_msgs.h"
#include "std_msgs.h"
#include "tf2_msgs.h"
#include "towsim_msgs.h"
#include "visualization_msgs.h"

namespace towsim::dds {

using TimeMsg = builtin_interfaces_msg_dds__Time_;
using HeaderMsg = std_msgs_msg_dds__Header_;
using OdometryMsg = nav_msgs_msg_dds__Odometry_;
using WrenchStampedMsg = geometry_msgs_msg_dds__WrenchStamped_;
using ClockMsg = rosgraph_msgs_msg_dds__Clock_;
using CableStateMsg = towsim_msgs_msg_dds__CableState_;
using BodyEnvironmentMsg = towsim_msgs_msg_dds__BodyEnvironment_;
using ActuatorCommandMsg = towsim_msgs_msg_dds__ActuatorCommand_;
using ActuatorStateMsg = towsim_msgs_msg_dds__ActuatorState_;
using WinchCommandMsg = towsim_msgs_msg_dds__WinchCommand_;
using SimStatusMsg = towsim_msgs_msg_dds__SimStatus_;
using SimControlMsg = towsim_msgs_msg_dds__SimControl_;
using SceneInfoMsg = towsim_msgs_msg_dds__SceneInfo_;
using RangeMsg = sensor_msgs_msg_dds__Range_;
using FluidPressureMsg = sensor_msgs_msg_dds__FluidPressure_;
using TransformStampedMsg = geometry_msgs_msg_dds__TransformStamped_;
using TfMsg = tf2_msgs_msg_dds__TFMessage_;
using MarkerMsg = visualization_msgs_msg_dds__Marker_;
using MarkerArrayMsg = visualization_msgs_msg_dds__MarkerArray_;
using ColorMsg = std_msgs_msg_dds__ColorRGBA_;
using ParticipantEntitiesInfoMsg = rmw_dds_common_msg_dds__ParticipantEntitiesInfo_;

}  // namespace towsim::dds
