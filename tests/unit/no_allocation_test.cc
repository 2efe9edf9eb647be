// Step does not allocate (DESIGN §1: a preallocated Workspace; issue 7). Built against a core
// compiled with EIGEN_RUNTIME_NO_MALLOC and asserts on, so any Eigen heap allocation while
// allocation is forbidden aborts; std containers are caught by counting the global operator new.
// The first steps may size work space (the sub-stepping backups, the first copies); after them
// a step of the cable alone, of a sphere-ended tow and of vehicles with either coupling must
// not allocate at all.

#include <atomic>
#include <cstdlib>
#include <new>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/simulation.h"
#include "steady_tow_model.h"

namespace {
std::atomic<long> g_news{0};
std::atomic<bool> g_counting{false};
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting.load()) ++g_news;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace towsim::core {
namespace {

using test::SteadyTowModel;

// a towing vehicle (no hydrodynamic coefficients needed here) pulling the cable with a sphere
Model WithVehicle(Coupling coupling) {
  Model m = SteadyTowModel();
  m.integrator.coupling = coupling;
  m.cable.start.kind = EndKind::kVehicle;
  m.cable.start.body = 0;
  m.cable.start.at_B = Vec3(0, 0, 0.2);
  Vehicle v;
  v.name = "tow_vehicle";
  v.params.mass = 6950;
  v.params.inertia = Vec3(397, 3970, 3069);
  v.params.r_g = Vec3(0, 0, 0.2);
  v.params.volume = 6950 / 1025.0;
  v.params.added_mass.diagonal() << 217, 8280, 8280, 624, 43263, 43263;
  v.params.x_uu = -35;
  v.params.has_propeller = true;
  v.params.max_thrust = 20000;
  v.position = Vec3(0, 0, 3.3);
  v.nu(0) = 6.0;
  v.command.thrust = 4000;
  m.vehicles.push_back(v);
  return m;
}

void ExpectStepsDoNotAllocate(const Model& model) {
  Simulation sim(model);
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(sim.Step().ok());  // warm-up: work space sized
  Eigen::internal::set_is_malloc_allowed(false);
  g_news = 0;
  g_counting = true;
  bool ok = true;
  for (int k = 0; k < 100 && ok; ++k) ok = sim.Step().ok();
  g_counting = false;
  Eigen::internal::set_is_malloc_allowed(true);
  ASSERT_TRUE(ok);
  EXPECT_EQ(g_news.load(), 0) << "operator new called during Step";
}

TEST(NoAllocation, CableWithASphere) { ExpectStepsDoNotAllocate(SteadyTowModel()); }
TEST(NoAllocation, VehicleStrongCoupling) {
  ExpectStepsDoNotAllocate(WithVehicle(Coupling::kStrong));
}
TEST(NoAllocation, VehicleStaggeredCoupling) {
  ExpectStepsDoNotAllocate(WithVehicle(Coupling::kStaggered));
}

// the whole sea: an irregular sea, a sheared current and a seabed the sphere rests near, with a
// vehicle (its hull strips and waterline sampled every step)
Model InASea(Model m) {
  Environment& env = m.environment;
  env.current = CurrentField::Profile({{0.0, Vec3(0.5, 0.2, 0.0)}, {100.0, Vec3(0.1, 0.0, 0.0)}});
  WaveSpectrum spectrum;
  spectrum.hs = 2.0;
  spectrum.tp = 8.0;
  spectrum.components = 100;
  env.waves = WaveField::Irregular(spectrum, 250.0, env.gravity, env.water_density);
  env.seabed = Seabed::Flat(250.0);
  SeabedContact contact;
  contact.friction = 0.5;
  env.seabed.set_contact(contact);
  return m;
}

TEST(NoAllocation, CableWithASphereInASea) { ExpectStepsDoNotAllocate(InASea(SteadyTowModel())); }
TEST(NoAllocation, VehicleInASea) {
  ExpectStepsDoNotAllocate(InASea(WithVehicle(Coupling::kStrong)));
}

}  // namespace
}  // namespace towsim::core
