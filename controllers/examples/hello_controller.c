/* hello_controller: a whole towsim controller in plain C against the Cyclone DDS C API and the
 * idlc-generated types of msgs/. It drives the tow vehicle with a constant thrust and a rudder
 * proportional to the heading error, answering every step (lockstep works).
 *   hello_controller [domain=0] [thrust_N=4165] [heading_deg=0]   (needs CYCLONEDDS_URI) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dds/dds.h"
#include "nav_msgs.h"
#include "towsim_msgs.h"

static dds_entity_t topic(dds_entity_t pp, const dds_topic_descriptor_t* type, const char* name) {
  return dds_create_topic(pp, type, name, NULL, NULL);
}

/* argv[i] as a finite number in [lo, hi] (else exit 2 naming it and the rule) */
static double arg(int argc, char** argv, int i, const char* name, double fallback, double lo,
                  double hi) {
  char* end = NULL;
  const double x = argc > i ? strtod(argv[i], &end) : fallback;
  if (argc > i && (end == argv[i] || *end != '\0' || !isfinite(x) || x < lo || x > hi)) {
    fprintf(stderr, "hello_controller: error: %s = %s: must be a number from %g to %g\n", name,
            argv[i], lo, hi);
    exit(2);
  }
  return x;
}

int main(int argc, char** argv) {
  if (argc > 1 && strcmp(argv[1], "--help") == 0) {
    printf("usage: hello_controller [domain=0] [thrust_N=4165] [heading_deg=0]\n"
           "  drives rt/towsim/tow_vehicle with a constant thrust and a rudder proportional to\n"
           "  the heading error, answering every step of the node (needs CYCLONEDDS_URI)\n");
    return 0;
  }
  const double domain = arg(argc, argv, 1, "domain", 0.0, 0.0, 232.0);
  if (domain != floor(domain)) return fprintf(stderr, "hello_controller: error: domain = %s: "
                                                      "must be an integer\n", argv[1]), 2;
  const double thrust = arg(argc, argv, 2, "thrust_N", 4165.0, -1e6, 1e6);
  const double heading = arg(argc, argv, 3, "heading_deg", 0.0, -360, 360) * M_PI / 180.0;
  const double gain = 1.0;
  const dds_entity_t pp = dds_create_participant((dds_domainid_t)domain, NULL, NULL);
  if (pp < 0) return fprintf(stderr, "hello_controller: %s\n", dds_strretcode(pp)), 1;
  dds_qos_t* qos = dds_create_qos(); /* the node's QoS: reliable, keep last 1, XCDR1 */
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(qos, 1, &xcdr1);
  const dds_entity_t status = dds_create_reader(
      pp, topic(pp, &towsim_msgs_msg_dds__SimStatus__desc, "rt/towsim/status"), qos, NULL);
  const dds_entity_t odom = dds_create_reader(
      pp, topic(pp, &nav_msgs_msg_dds__Odometry__desc, "rt/towsim/tow_vehicle/odom"), qos, NULL);
  const dds_entity_t command = dds_create_writer(
      pp, topic(pp, &towsim_msgs_msg_dds__ActuatorCommand__desc, "rt/towsim/tow_vehicle/command"),
      qos, NULL);
  dds_delete_qos(qos);
  /* sleep until a status comes (a waitset: no polling); the node repeats it while it waits */
  const dds_entity_t waitset = dds_create_waitset(pp);
  dds_waitset_attach(waitset, dds_create_readcondition(status, DDS_ANY_STATE), 0);
  for (int done = 0; !done;) {
    void *s[1] = {NULL}, *o[1] = {NULL};
    dds_sample_info_t si, oi;
    dds_waitset_wait(waitset, NULL, 0, DDS_SECS(1));
    if (dds_take(status, s, &si, 1, 1) < 1 || !si.valid_data || dds_read(odom, o, &oi, 1, 1) < 1) {
      if (s[0]) dds_return_loan(status, s, 1); /* (a sample without data, no odometry yet) */
      continue;
    }
    const towsim_msgs_msg_dds__SimStatus_* st = s[0]; /* the step to answer */
    const geometry_msgs_msg_dds__Quaternion_* q =
        &((nav_msgs_msg_dds__Odometry_*)o[0])->pose.pose.orientation;
    const double yaw = atan2(2 * (q->w * q->z + q->x * q->y), 1 - 2 * (q->y * q->y + q->z * q->z));
    const double error = remainder(heading - yaw, 2 * M_PI); /* the short way round */
    towsim_msgs_msg_dds__ActuatorCommand_ cmd = {
        .header = {.stamp = st->header.stamp, .frame_id = ""},
        .step = st->step,
        .thrust = thrust,
        .rudder = fmax(-0.35, fmin(0.35, gain * error))};
    dds_write(command, &cmd);
    done = st->state >= towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;
    dds_return_loan(status, s, 1);
    dds_return_loan(odom, o, 1);
  }
  return dds_delete(pp) < 0;
}
