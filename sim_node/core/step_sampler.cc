#include "core/step_sampler.h"

namespace towsim::core {

void StepSampler::Resize(StepInputs* in) const {
  in->waves.nodes.assign(system_.total_array_nodes(), WaveSample());
  in->waves.elements.assign(system_.total_array_nodes(), GaussWaves());
  in->supports.assign(system_.num_ends(), SupportMotion());
  in->waves.spheres.assign(system_.num_spheres(), WaveSample());
  const size_t nv = system_.model().vehicles.size();
  in->vehicle_flow_start.assign(nv, VehicleFlow());
  in->vehicle_flow_end.assign(nv, VehicleFlow());
}

void StepSampler::SampleWaves(const Eigen::VectorXd& q, double t, StepInputs* in) const {
  const EnvironmentField& sea = system_.sea();
  // nodes: the waves at r and their derivative along r' (= d/dx, x the unstretched arc length)
  for (int c = 0; c < system_.num_cables(); ++c)
    for (int n = 0; n < system_.num_nodes(c); ++n) {
      const int o = system_.CableDof(n, c);
      in->waves.nodes[system_.NodeIndex(n, c)] = sea.Waves(q.segment<3>(o), q.segment<3>(o + 3), t);
    }
  // ... interpolated to the Gauss points of the elements of nominal length (the drum element's
  // change with its rest length: System interpolates its own)
  for (int c = 0; c < system_.num_cables(); ++c)
    for (int e = system_.has_winch(c) ? 1 : 0; e < system_.NumElements(c); ++e) {
      const int i = system_.NodeIndex(e, c);
      in->waves.elements[i] = WavesAtGaussPoints(
          system_.element(c), NodeWaves(in->waves.nodes[i], in->waves.nodes[i + 1]));
    }
  for (int s = 0; s < system_.num_spheres(); ++s)
    in->waves.spheres[s] = sea.Waves(q.segment<3>(system_.SphereDof(s)), Vec3::Zero(), t);
  in->has_waves = true;
}

void StepSampler::SampleVehicleFlows(const State& start, double h, StepInputs* in) const {
  const Model& model = system_.model();
  const EnvironmentField& sea = system_.sea();
  const CouplingHistory& history = start.coupling;
  const double t0 = start.t;
  for (size_t v = 0; v < model.vehicles.size(); ++v) {
    const VehicleParams& vp = model.vehicles[v].params;
    const VehicleState& vs = start.vehicles[v];
    if (sea.uniform()) {
      in->vehicle_flow_start[v] = in->vehicle_flow_end[v] = UniformFlow(sea.uniform_current());
      continue;
    }
    in->vehicle_flow_start[v] = history.flow_time == t0
                                    ? history.flow_end[v]
                                    : SampleVehicleFlow(vp, sea, vs.p_W, vs.q_WB, t0);
    const Vec3 p1 = vs.p_W + h * (vs.q_WB * Vec3(vs.nu.head<3>()));
    in->vehicle_flow_end[v] = SampleVehicleFlow(vp, sea, p1, vs.q_WB, t0 + h);
  }
}

void StepSampler::TakeMotions(const State& state, StepInputs* in) const {
  in->supports = state.supports;  // same size: copies in place
  const int nw = system_.num_winches();
  in->drums.resize(nw);  // the same size after the first call: no allocation
  for (int w = 0; w < nw; ++w) in->drums[w] = state.winches[w].drum;
}

}  // namespace towsim::core
