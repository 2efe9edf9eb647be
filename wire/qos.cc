#include "wire/qos.h"

namespace towsim::wire {

dds_qos_t* ReliableQos(int depth, bool transient_local) {
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, depth);
  dds_qset_durability(q,
                      transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q, 1, &xcdr1);
  return q;
}

dds_qos_t* ProfileQos(QosProfile profile, int state_depth) {
  switch (profile) {
    case QosProfile::kLatched:
      return ReliableQos(1, true);
    case QosProfile::kCommand:
      return ReliableQos(kCommandDepth, false);
    case QosProfile::kControl:
      return ReliableQos(kControlDepth, false);
    case QosProfile::kState:
      break;
  }
  return ReliableQos(state_depth, false);
}

}  // namespace towsim::wire
