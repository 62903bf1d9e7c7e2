// SPDX-License-Identifier: MIT
#include "physics.hpp"

#include <algorithm>
#include <cmath>

#include <box2d/box2d.h>

#include "robot_model.hpp"
#include "spatial.hpp"

// Box2D 2.4 times every island of every step with b2Timer, which reads the wall clock
// (gettimeofday) four times per island: a third of a 100-robot tick, spent on profile numbers
// swarmpath never reads, and a wall-clock read inside the simulator. libbox2d calls b2Timer
// through its PLT, so these definitions interpose the library's: the timers read nothing and
// report zero. Box2D's results do not depend on them (they only fill b2Profile).
b2Timer::b2Timer() = default;

void b2Timer::Reset() {}

float b2Timer::GetMilliseconds() const { return 0.0f; }

namespace swarmpath::sim {

namespace {

// A stopped robot brakes: its body is made this much heavier, so that a robot bumping into it
// barely moves it (velocity-driven Box2D bodies would otherwise share momentum equally, and a
// static subgoal would be shoved at half the pusher's speed). ARGoS's foot-bot gets the same
// effect from the friction of its locked treels.
constexpr float kBrakeMassFactor = 100.0f;

// A region's world holds every obstacle within this distance of the region, so that a robot
// whose centre is inside meets every wall its body can touch.
constexpr double kRegionMargin = 0.5;

b2MassData robot_mass(float factor) {
  const float r = static_cast<float>(kRobotRadius);
  b2MassData md;
  md.mass = factor * b2_pi * r * r;  // density 1
  md.center.SetZero();
  md.I = 0.5f * md.mass * r * r;
  return md;
}

std::unique_ptr<b2World> make_b2_world() {
  auto world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
  // low speeds (<= 3 cm per step) against 10 cm walls: no tunnelling, so no TOI sub-stepping
  world->SetContinuousPhysics(false);
  world->SetAllowSleeping(true);
  // robots are driven by velocity, never by forces: skip Box2D's per-step pass that clears them
  world->SetAutoClearForces(false);
  return world;
}

void add_obstacle(b2Body* ground, const Shape& sh) {
  b2FixtureDef fd;
  fd.friction = 0.0f;
  if (sh.kind == ShapeKind::kCircle) {
    b2CircleShape circle;
    circle.m_p.Set(static_cast<float>(sh.center.x), static_cast<float>(sh.center.y));
    circle.m_radius = static_cast<float>(sh.radius);
    fd.shape = &circle;
    ground->CreateFixture(&fd);
  } else {
    b2PolygonShape box;
    box.SetAsBox(static_cast<float>(sh.half.x), static_cast<float>(sh.half.y),
                 b2Vec2(static_cast<float>(sh.center.x), static_cast<float>(sh.center.y)),
                 static_cast<float>(std::atan2(sh.s, sh.c)));
    fd.shape = &box;
    ground->CreateFixture(&fd);
  }
}

// One byte of every cache line of the object at p (blocks from Box2D's allocator are not
// line-aligned: a 184-byte body spans four lines).
template <typename T>
unsigned touch(const T* p) {
  const auto* bytes = reinterpret_cast<const volatile unsigned char*>(p);
  unsigned acc = bytes[sizeof(T) - 1];
  for (std::size_t k = 0; k < sizeof(T); k += 64) acc += bytes[k];
  return acc;
}

// Reads a region's bodies, fixtures, shapes, broad-phase nodes and contacts in sweeps over the
// array of its bodies. Box2D's step walks linked lists, one dependent cache miss after another
// once a swarm outgrows the cache; these loads have independent addresses, so the core keeps
// many in flight, and the step then finds its data in cache. (__builtin_prefetch in their place
// measured no gain; real loads did.) Returns a checksum nobody reads.
unsigned warm_region(const b2World& world, std::span<b2Body* const> bodies) {
  unsigned acc = 0;
  for (const b2Body* b : bodies) acc += touch(b);
  const b2BroadPhase& broad_phase = world.GetContactManager().m_broadPhase;
  for (const b2Body* b : bodies) {
    const b2Fixture* f = b->GetFixtureList();
    acc += touch(f);
    acc += touch(static_cast<const b2CircleShape*>(f->GetShape()));
    if (const b2ContactEdge* e = b->GetContactList()) acc += touch(e->contact);
  }
  for (const b2Body* b : bodies) {
    // a fixture's proxy array is Box2D's public b2FixtureProxy, reached through its AABB
    const auto* proxy = reinterpret_cast<const b2FixtureProxy*>(&b->GetFixtureList()->GetAABB(0));
    acc += touch(&broad_phase.GetFatAABB(proxy->proxyId));
    for (const b2ContactEdge* e = b->GetContactList(); e != nullptr; e = e->next) {
      if (e->next != nullptr) acc += touch(e->next->contact);
    }
  }
  return acc;
}

struct Wheels {
  double left = 0.0;  // [m/s]
  double right = 0.0;
};

}  // namespace

struct Physics::Impl {
  PhysicsLayout layout;
  CellFrame regions;
  std::vector<std::unique_ptr<b2World>> worlds;  // one per region, row-major
  std::vector<std::vector<b2Body*>> members;     // each region's robot bodies
  std::vector<b2Body*> robots;
  std::vector<int> region;  // the region each robot's body lives in
  std::vector<std::uint8_t> braked;
  std::vector<Wheels> wheels;                  // set_wheels' last call, applied at the next step
  std::vector<Pose> poses;                     // after the last step
  std::vector<std::pair<int, int>> crossings;  // (robot, new region) found in a step
  b2MassData free_mass = robot_mass(1.0f);
  b2MassData braked_mass = robot_mass(kBrakeMassFactor);
  unsigned warm_sink = 0;

  int region_at(const b2Vec2& p) const { return regions.index({p.x, p.y}); }

  b2Body* create_robot(int r, const b2Vec2& p, float angle, std::size_t id) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = p;
    def.angle = angle;
    def.userData.pointer = id;  // the robot id, never an address
    b2Body* body = worlds[static_cast<std::size_t>(r)]->CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(kRobotRadius);
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = 1.0f;
    fd.friction = 0.0f;
    fd.restitution = 0.0f;
    body->CreateFixture(&fd);
    members[static_cast<std::size_t>(r)].push_back(body);
    return body;
  }

  // Differential drive (SPEC §1.2) on one body, from its heading before the step.
  void drive(b2Body* body, std::size_t i) {
    const Wheels& w = wheels[i];
    const std::uint8_t brake = w.left == 0.0 && w.right == 0.0 ? 1 : 0;
    if (brake != braked[i]) {
      body->SetMassData(brake ? &braked_mass : &free_mass);
      braked[i] = brake;
    }
    const double v = 0.5 * (w.left + w.right);
    const double omega = (w.right - w.left) / kWheelBase;
    const b2Rot& q = body->GetTransform().q;
    // setting a non-zero velocity wakes a sleeping body; zero leaves it asleep
    body->SetLinearVelocity(b2Vec2(static_cast<float>(v * q.c), static_cast<float>(v * q.s)));
    body->SetAngularVelocity(static_cast<float>(omega));
  }

  // A robot whose centre crossed into another region moves to that region's world with its
  // pose, velocities and brake.
  void migrate(std::size_t i, int to) {
    b2Body* old = robots[i];
    b2Body* body = create_robot(to, old->GetPosition(), old->GetAngle(), i);
    if (braked[i]) body->SetMassData(&braked_mass);
    body->SetLinearVelocity(old->GetLinearVelocity());
    body->SetAngularVelocity(old->GetAngularVelocity());
    auto& from = members[static_cast<std::size_t>(region[i])];
    *std::find(from.begin(), from.end(), old) = from.back();
    from.pop_back();
    worlds[static_cast<std::size_t>(region[i])]->DestroyBody(old);
    robots[i] = body;
    region[i] = to;
  }
};

Physics::Physics(std::span<const Shape> obstacles, const PhysicsLayout& layout)
    : impl_(std::make_unique<Impl>()) {
  impl_->layout = layout;
  const int count = layout.nx * layout.ny;
  if (count > 1) impl_->regions = CellFrame(layout.bounds, layout.nx, layout.ny);  // else one cell
  for (int r = 0; r < count; ++r) {
    impl_->worlds.push_back(make_b2_world());
    impl_->members.emplace_back();
    b2BodyDef def;
    def.type = b2_staticBody;
    b2Body* ground = impl_->worlds.back()->CreateBody(&def);
    const Aabb b = count > 1 ? impl_->regions.cell_bounds(r) : layout.bounds;
    const Aabb near{b.lo - Vec2{kRegionMargin, kRegionMargin}, b.hi + Vec2{kRegionMargin, kRegionMargin}};
    for (const Shape& sh : obstacles) {
      if (count == 1 || sh.bounds.overlaps(near)) add_obstacle(ground, sh);
    }
  }
}

Physics::~Physics() = default;

int Physics::add_robot(Vec2 position, double yaw) {
  const b2Vec2 p(static_cast<float>(position.x), static_cast<float>(position.y));
  const int r = impl_->region_at(p);
  const std::size_t id = impl_->robots.size();
  b2Body* body = impl_->create_robot(r, p, static_cast<float>(yaw), id);
  impl_->robots.push_back(body);
  impl_->region.push_back(r);
  impl_->braked.push_back(0);
  impl_->wheels.emplace_back();
  const b2Transform& t = body->GetTransform();
  impl_->poses.push_back(Pose{{t.p.x, t.p.y}, t.q.c, t.q.s});
  return static_cast<int>(id);
}

void Physics::set_wheels(int id, double left_m_s, double right_m_s) {
  impl_->wheels[static_cast<std::size_t>(id)] = {left_m_s, right_m_s};
}

void Physics::step(double dt, int velocity_iterations, int position_iterations) {
  Impl& m = *impl_;
  m.crossings.clear();
  for (std::size_t r = 0; r < m.worlds.size(); ++r) {
    const std::vector<b2Body*>& bodies = m.members[r];
    if (m.robots.size() >= m.layout.warm_from_robots) m.warm_sink += warm_region(*m.worlds[r], bodies);
    for (b2Body* b : bodies) m.drive(b, b->GetUserData().pointer);
    m.worlds[r]->Step(static_cast<float>(dt), velocity_iterations, position_iterations);
    for (b2Body* b : bodies) {
      const std::size_t i = b->GetUserData().pointer;
      const b2Transform& t = b->GetTransform();
      m.poses[i] = Pose{{t.p.x, t.p.y}, t.q.c, t.q.s};
      if (m.worlds.size() > 1) {
        const int to = m.region_at(t.p);
        if (to != static_cast<int>(r)) m.crossings.emplace_back(static_cast<int>(i), to);
      }
    }
  }
  std::sort(m.crossings.begin(), m.crossings.end());
  for (const auto& [i, to] : m.crossings) m.migrate(static_cast<std::size_t>(i), to);
}

void Physics::read_poses(std::span<Pose> out) const {
  std::copy(impl_->poses.begin(), impl_->poses.end(), out.begin());
}

int Physics::robot_count() const { return static_cast<int>(impl_->robots.size()); }

int Physics::contact_count() const {
  int n = 0;
  for (const auto& world : impl_->worlds) n += world->GetContactCount();
  return n;
}

}  // namespace swarmpath::sim
