// SPDX-License-Identifier: MIT
#include "physics.hpp"

#include <cmath>

#include <box2d/box2d.h>

#include "robot_model.hpp"

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

b2MassData robot_mass(float factor) {
  const float r = static_cast<float>(kRobotRadius);
  b2MassData md;
  md.mass = factor * b2_pi * r * r;  // density 1
  md.center.SetZero();
  md.I = 0.5f * md.mass * r * r;
  return md;
}

}  // namespace

struct Physics::Impl {
  b2World world{b2Vec2(0.0f, 0.0f)};
  std::vector<b2Body*> robots;
  std::vector<std::uint8_t> braked;
  b2MassData free_mass = robot_mass(1.0f);
  b2MassData braked_mass = robot_mass(kBrakeMassFactor);
};

Physics::Physics(std::span<const Shape> obstacles) : impl_(std::make_unique<Impl>()) {
  // low speeds (<= 3 cm per step) against 10 cm walls: no tunnelling, so no TOI sub-stepping
  impl_->world.SetContinuousPhysics(false);
  impl_->world.SetAllowSleeping(true);
  // robots are driven by velocity, never by forces: skip Box2D's per-step pass that clears them
  impl_->world.SetAutoClearForces(false);
  b2BodyDef def;
  def.type = b2_staticBody;
  b2Body* ground = impl_->world.CreateBody(&def);
  for (const Shape& sh : obstacles) {
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
}

Physics::~Physics() = default;

int Physics::add_robot(Vec2 position, double yaw) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position.Set(static_cast<float>(position.x), static_cast<float>(position.y));
  def.angle = static_cast<float>(yaw);
  def.userData.pointer = impl_->robots.size();  // the robot id, never an address
  b2Body* body = impl_->world.CreateBody(&def);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(kRobotRadius);
  b2FixtureDef fd;
  fd.shape = &circle;
  fd.density = 1.0f;
  fd.friction = 0.0f;
  fd.restitution = 0.0f;
  body->CreateFixture(&fd);
  impl_->robots.push_back(body);
  impl_->braked.push_back(0);
  return static_cast<int>(impl_->robots.size()) - 1;
}

void Physics::set_wheels(int id, double left_m_s, double right_m_s) {
  const auto i = static_cast<std::size_t>(id);
  b2Body* body = impl_->robots[i];
  const std::uint8_t brake = left_m_s == 0.0 && right_m_s == 0.0 ? 1 : 0;
  if (brake != impl_->braked[i]) {
    body->SetMassData(brake ? &impl_->braked_mass : &impl_->free_mass);
    impl_->braked[i] = brake;
  }
  const double v = 0.5 * (left_m_s + right_m_s);
  const double omega = (right_m_s - left_m_s) / kWheelBase;
  const b2Rot& q = body->GetTransform().q;
  // setting a non-zero velocity wakes a sleeping body; zero leaves it asleep
  body->SetLinearVelocity(b2Vec2(static_cast<float>(v * q.c), static_cast<float>(v * q.s)));
  body->SetAngularVelocity(static_cast<float>(omega));
}

void Physics::step(double dt, int velocity_iterations, int position_iterations) {
  impl_->world.Step(static_cast<float>(dt), velocity_iterations, position_iterations);
}

void Physics::read_poses(std::span<Pose> out) const {
  for (std::size_t i = 0; i < impl_->robots.size(); ++i) {
    const b2Transform& t = impl_->robots[i]->GetTransform();
    Pose& p = out[i];
    p.p = {t.p.x, t.p.y};
    p.c = t.q.c;
    p.s = t.q.s;
  }
}

int Physics::robot_count() const { return static_cast<int>(impl_->robots.size()); }

int Physics::contact_count() const { return impl_->world.GetContactCount(); }

}  // namespace swarmpath::sim
