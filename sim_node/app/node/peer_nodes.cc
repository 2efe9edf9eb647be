#include "app/node/peer_nodes.h"

#include "dds/qos.h"

namespace towsim::app {
namespace {

dds::Qos PeerQos() {
  dds::Qos q = dds::SceneInfoQos();
  dds_qset_ignorelocal(q.get(), DDS_IGNORELOCAL_PARTICIPANT);  // not this node's own writer
  return q;
}

}  // namespace

PeerNodes::PeerNodes(const dds::Participant& participant, const wire::TopicNames& names)
    : topic_(participant, &towsim_msgs_msg_dds__SceneInfo__desc,
             names.Name(wire::Topic::kSceneInfo)),
      reader_(participant, topic_, PeerQos()),
      waitset_(participant) {
  waitset_.Attach(reader_.condition());
}

bool PeerNodes::Poll() {
  bool added = false;
  reader_.TakeEach([&](const dds::SceneInfoMsg& msg, const dds_sample_info_t& info) {
    const auto it = writer_index_.find(info.publication_handle);
    if (it == writer_index_.end()) {
      writer_index_[info.publication_handle] = run_ids_.size();
      run_ids_.push_back(msg.run_id);
      added = true;
    } else {
      run_ids_[it->second] = msg.run_id;  // a reset: a new run id
    }
  });
  return added;
}

std::vector<std::string> PeerNodes::run_ids() const { return run_ids_; }

std::string PeerNodes::Names() const {
  std::string names;
  for (const std::string& id : run_ids_) names += (names.empty() ? "run id " : ", run id ") + id;
  return names;
}

}  // namespace towsim::app
