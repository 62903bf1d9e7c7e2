// SPDX-License-Identifier: MIT
#include "recording.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <zlib.h>

#include <nlohmann/json.hpp>

#include "config_error.hpp"
#include "hash.hpp"

namespace swarmpath::sim {

namespace {

using Json = nlohmann::ordered_json;

constexpr std::size_t kFrameHeaderBytes = 4;
constexpr std::size_t kRobotBytes = 2 + 2 + 1 + 1 + 1 + 4 + 4;  // x, y, heading, led, state, parent, child
constexpr std::size_t kChangeBytes = 12;
constexpr std::uint64_t kMaxBodyBytes = 1ULL << 32;  // what the u32 lengths can say

Json vec(Vec2 v) { return Json::array({v.x, v.y}); }

Vec2 vec_of(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>()}; }

Json points_json(const std::vector<Vec2>& points) {
  Json a = Json::array();
  for (const Vec2& p : points) a.push_back(vec(p));
  return a;
}

Json shape_json(const Shape& s) {
  if (s.kind == ShapeKind::kCircle)
    return {{"kind", "circle"}, {"center", vec(s.center)}, {"radius", s.radius}};
  return {{"kind", "box"}, {"center", vec(s.center)}, {"half", vec(s.half)}, {"c", s.c}, {"s", s.s}};
}

Shape shape_of(const nlohmann::json& j) {
  const std::string kind = j.at("kind").get<std::string>();
  if (kind == "circle") return Shape::circle(vec_of(j.at("center")), j.at("radius").get<double>());
  if (kind != "box") throw std::runtime_error("unknown obstacle kind \"" + kind + "\"");
  return Shape::box(vec_of(j.at("center")), 2.0 * vec_of(j.at("half")),
                    std::atan2(j.at("s").get<double>(), j.at("c").get<double>()));
}

Json rows_json(const std::vector<RowName>& rows) {
  Json a = Json::array();
  for (const RowName& r : rows) a.push_back({{"row", r.row}, {"label", r.label}});
  return a;
}

std::vector<RowName> rows_of(const nlohmann::json& j) {
  std::vector<RowName> rows;
  for (const nlohmann::json& r : j)
    rows.push_back({r.at("row").get<std::string>(), r.at("label").get<std::string>()});
  return rows;
}

Json header_json(const Recording& r) {
  Json j;
  j["format"] = "swarmpath recording";
  j["generator"] = r.generator;
  j["scenario"] = {{"name", r.scenario_name},
                   {"file", r.scenario_file},
                   {"env_class", std::string(to_string(r.env_class))},
                   {"arena_size", vec(r.arena_size)},
                   {"nest", vec(r.nest)},
                   {"goal", vec(r.goal)},
                   {"deployment", {{"center", vec(r.deployment.center)}, {"size", vec(r.deployment.size)}}},
                   {"toml", r.scenario_toml}};
  Json obstacles = Json::array();
  for (const Shape& s : r.obstacles) obstacles.push_back(shape_json(s));
  j["scenario"]["obstacles"] = obstacles;
  j["params_toml"] = r.params_toml;
  j["mode"] = std::string(to_string(r.mode));
  j["seed"] = std::to_string(r.seed);  // as text: JSON readers keep 53 bits of a number
  j["robots"] = r.robots;
  j["robot_radius"] = r.robot_radius;
  j["ticks_per_second"] = r.ticks_per_second;
  j["max_ticks"] = r.max_ticks;
  j["every"] = r.every;
  j["origin"] = vec(r.origin);
  j["quantum"] = r.quantum;
  j["frames"] = r.frame_count();
  j["changes"] = r.changes.size();
  Json states = Json::array();
  for (const auto& [code, name] : r.state_names) states.push_back({{"code", code}, {"name", name}});
  j["states"] = states;
  Json leds = Json::array();
  for (const LedName& l : r.leds) leds.push_back({{"name", l.name}, {"rgb", {l.rgb.r, l.rgb.g, l.rgb.b}}});
  j["leds"] = leds;
  j["pf_rows"] = rows_json(r.pf_rows);
  j["ta_rows"] = rows_json(r.ta_rows);
  j["result"] = {{"success", r.success},
                 {"ticks", r.ticks},
                 {"state_hash", to_hex(r.state_hash)},
                 {"allocated", r.allocated}};
  Json milestones = Json::array();
  for (const Milestone& m : r.milestones)
    milestones.push_back({{"name", m.name}, {"label", m.label}, {"tick", m.tick}});
  j["milestones"] = milestones;
  Json paths = Json::array();
  for (const RecordedPath& p : r.paths) {
    paths.push_back({{"name", p.name},
                     {"label", p.label},
                     {"tick", p.tick},
                     {"points", points_json(p.points)},
                     {"robots", p.robots},
                     {"length_m", p.length_m}});
  }
  j["paths"] = paths;
  Json notes = Json::array();
  for (const RecordedNote& n : r.notes)
    notes.push_back({{"tick", n.tick}, {"robot", n.robot}, {"text", n.text}});
  j["notes"] = notes;
  return j;
}

void header_from_json(const nlohmann::json& j, Recording& r, std::size_t& frames, std::size_t& changes) {
  if (j.at("format").get<std::string>() != "swarmpath recording")
    throw std::runtime_error("not a swarmpath recording");
  r.generator = j.at("generator").get<std::string>();
  const nlohmann::json& s = j.at("scenario");
  r.scenario_name = s.at("name").get<std::string>();
  r.scenario_file = s.at("file").get<std::string>();
  const std::string env = s.at("env_class").get<std::string>();
  r.env_class = env == "complex"    ? EnvClass::kComplex
                : env == "obstacle" ? EnvClass::kObstacle
                                    : EnvClass::kOpen;
  r.arena_size = vec_of(s.at("arena_size"));
  r.nest = vec_of(s.at("nest"));
  r.goal = vec_of(s.at("goal"));
  r.deployment = {vec_of(s.at("deployment").at("center")), vec_of(s.at("deployment").at("size"))};
  r.scenario_toml = s.at("toml").get<std::string>();
  for (const nlohmann::json& o : s.at("obstacles")) r.obstacles.push_back(shape_of(o));
  r.params_toml = j.at("params_toml").get<std::string>();
  const std::optional<Mode> mode = parse_mode(j.at("mode").get<std::string>());
  if (!mode) throw std::runtime_error("unknown mode " + j.at("mode").dump());
  r.mode = *mode;
  r.seed = std::stoull(j.at("seed").get<std::string>());
  r.robots = j.at("robots").get<int>();
  r.robot_radius = j.at("robot_radius").get<double>();
  r.ticks_per_second = j.at("ticks_per_second").get<int>();
  r.max_ticks = j.at("max_ticks").get<std::int64_t>();
  r.every = j.at("every").get<std::int64_t>();
  r.origin = vec_of(j.at("origin"));
  r.quantum = j.at("quantum").get<double>();
  frames = j.at("frames").get<std::size_t>();
  changes = j.at("changes").get<std::size_t>();
  for (const nlohmann::json& e : j.at("states"))
    r.state_names.emplace_back(e.at("code").get<int>(), e.at("name").get<std::string>());
  for (const nlohmann::json& e : j.at("leds")) {
    const nlohmann::json& c = e.at("rgb");
    r.leds.push_back(
        {e.at("name").get<std::string>(),
         {c.at(0).get<std::uint8_t>(), c.at(1).get<std::uint8_t>(), c.at(2).get<std::uint8_t>()}});
  }
  r.pf_rows = rows_of(j.at("pf_rows"));
  r.ta_rows = rows_of(j.at("ta_rows"));
  const nlohmann::json& res = j.at("result");
  r.success = res.at("success").get<bool>();
  r.ticks = res.at("ticks").get<std::int64_t>();
  r.state_hash = std::stoull(res.at("state_hash").get<std::string>(), nullptr, 16);
  r.allocated = res.at("allocated").get<int>();
  for (const nlohmann::json& m : j.at("milestones")) {
    r.milestones.push_back({m.at("name").get<std::string>(), m.at("label").get<std::string>(),
                            m.at("tick").get<std::int64_t>()});
  }
  for (const nlohmann::json& p : j.at("paths")) {
    RecordedPath path;
    path.name = p.at("name").get<std::string>();
    path.label = p.at("label").get<std::string>();
    path.tick = p.at("tick").get<std::int64_t>();
    for (const nlohmann::json& q : p.at("points")) path.points.push_back(vec_of(q));
    path.robots = p.at("robots").get<std::vector<int>>();
    path.length_m = p.at("length_m").get<double>();
    r.paths.push_back(std::move(path));
  }
  for (const nlohmann::json& n : j.at("notes")) {
    r.notes.push_back(
        {n.at("tick").get<std::int64_t>(), n.at("robot").get<int>(), n.at("text").get<std::string>()});
  }
}

// little-endian writers and readers
void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffU));
}

class ByteWriter {
 public:
  explicit ByteWriter(std::size_t reserve) { bytes_.reserve(reserve); }

  void u8(std::uint8_t v) { bytes_.push_back(v); }

  void u16(std::uint16_t v) {
    bytes_.push_back(static_cast<std::uint8_t>(v & 0xffU));
    bytes_.push_back(static_cast<std::uint8_t>(v >> 8));
  }

  void i32(std::int32_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<std::uint8_t>((u >> (8 * i)) & 0xffU));
  }

  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::vector<std::uint8_t>& b) : b_(b) {}

  std::uint8_t u8() { return b_[at_++]; }

  std::uint16_t u16() {
    const auto v = static_cast<std::uint16_t>(b_[at_] | (b_[at_ + 1] << 8));
    at_ += 2;
    return v;
  }

  std::int32_t i32() {
    std::uint32_t u = 0;
    for (int i = 0; i < 4; ++i)
      u |= static_cast<std::uint32_t>(b_[at_ + static_cast<std::size_t>(i)]) << (8 * i);
    at_ += 4;
    return static_cast<std::int32_t>(u);
  }

 private:
  const std::vector<std::uint8_t>& b_;
  std::size_t at_ = 0;
};

std::uint32_t get_u32(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]))
         << (8 * i);
  return v;
}

std::size_t body_size(std::size_t frames, std::size_t robots, std::size_t changes) {
  return frames * (kFrameHeaderBytes + kRobotBytes * robots) + changes * kChangeBytes;
}

}  // namespace

double Recording::yaw(std::size_t frame, int robot) const {
  const std::size_t k = frame * static_cast<std::size_t>(robots) + static_cast<std::size_t>(robot);
  return 2.0 * std::numbers::pi * heading[k] / 256.0;
}

std::string_view Recording::state_name(int code) const {
  for (const auto& [c, name] : state_names) {
    if (c == code) return name;
  }
  return "?";
}

std::uint16_t quantise(double x, double origin, double quantum) {
  const double q = std::round((x - origin) / quantum);
  if (!(q > 0.0)) return 0;  // NaN too
  if (q >= 65535.0) return 65535;
  return static_cast<std::uint16_t>(q);
}

std::uint8_t heading_code(double yaw) {
  const double turns = yaw / (2.0 * std::numbers::pi);
  const double steps = std::round((turns - std::floor(turns)) * 256.0);
  return static_cast<std::uint8_t>(static_cast<int>(steps) & 0xff);
}

std::string encode_recording(const Recording& r) {
  const std::size_t n = static_cast<std::size_t>(r.robots);
  const std::size_t frames = r.frame_count();
  ByteWriter body(body_size(frames, n, r.changes.size()));
  for (std::size_t f = 0; f < frames; ++f) {
    const std::size_t k0 = f * n;
    body.i32(static_cast<std::int32_t>(r.frame_ticks[f]));
    // positions as differences from the previous frame: resting robots and subgoals cost zeros
    for (std::size_t i = 0; i < n; ++i)
      body.u16(static_cast<std::uint16_t>(r.qx[k0 + i] - (f > 0 ? r.qx[k0 - n + i] : 0)));
    for (std::size_t i = 0; i < n; ++i)
      body.u16(static_cast<std::uint16_t>(r.qy[k0 + i] - (f > 0 ? r.qy[k0 - n + i] : 0)));
    for (std::size_t i = 0; i < n; ++i) body.u8(r.heading[k0 + i]);
    for (std::size_t i = 0; i < n; ++i) body.u8(r.led[k0 + i]);
    for (std::size_t i = 0; i < n; ++i) body.u8(r.state[k0 + i]);
    for (std::size_t i = 0; i < n; ++i) body.i32(r.parent[k0 + i]);
    for (std::size_t i = 0; i < n; ++i) body.i32(r.child[k0 + i]);
  }
  for (const StateChange& c : r.changes) {
    body.i32(c.tick);
    body.i32(c.robot);
    body.u8(c.from);
    body.u8(c.to);
    body.u8(c.pf_row);
    body.u8(c.ta_row);
  }
  const std::vector<std::uint8_t>& raw = body.bytes();
  if (raw.size() >= kMaxBodyBytes)
    throw std::runtime_error("recording too large (over 4 GiB): record fewer frames");
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packed_size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size, raw.data(),
                static_cast<uLong>(raw.size()), 6) != Z_OK) {
    throw std::runtime_error("recording: zlib could not compress the frames");
  }
  packed.resize(packed_size);

  const std::string header = header_json(r).dump();
  std::string out(kRecordingMagic);
  put_u32(out, kRecordingVersion);
  put_u32(out, static_cast<std::uint32_t>(header.size()));
  out += header;
  put_u32(out, static_cast<std::uint32_t>(packed.size()));
  put_u32(out, static_cast<std::uint32_t>(raw.size()));
  out += packed;
  return out;
}

Recording decode_recording(std::string_view bytes, const std::string& name) {
  const auto bad = [&](const std::string& why) { return ConfigError(name, 0, "", why); };
  if (bytes.size() < 16 || bytes.substr(0, kRecordingMagic.size()) != kRecordingMagic)
    throw bad("not a swarmpath recording (.swrec): the file does not start with its signature");
  const std::uint32_t version = get_u32(bytes, 8);
  if (version != kRecordingVersion) {
    throw bad("recording format version " + std::to_string(version) + " (this build reads version " +
              std::to_string(kRecordingVersion) + ")");
  }
  const std::size_t header_size = get_u32(bytes, 12);
  if (bytes.size() < 16 + header_size + 8) throw bad("truncated: the file ends inside its header");
  Recording r;
  std::size_t frames = 0, changes = 0;
  try {
    header_from_json(nlohmann::json::parse(bytes.substr(16, header_size)), r, frames, changes);
  } catch (const std::exception& e) {
    throw bad(std::string("malformed header: ") + e.what());
  }
  if (r.robots < 0 || r.robots > kMaxRobots)
    throw bad("robot count out of range: " + std::to_string(r.robots));
  if (!(r.quantum > 0.0) || r.every < 1) throw bad("malformed header: quantum and every must be positive");
  const std::size_t at = 16 + header_size;
  const std::size_t packed_size = get_u32(bytes, at);
  const std::size_t raw_size = get_u32(bytes, at + 4);
  if (bytes.size() != at + 8 + packed_size) {
    throw bad("truncated or padded: the body should be " + std::to_string(packed_size) +
              " bytes, the file has " + std::to_string(bytes.size() - at - 8));
  }
  const std::size_t n = static_cast<std::size_t>(r.robots);
  if (frames > kMaxBodyBytes || changes > kMaxBodyBytes || raw_size != body_size(frames, n, changes)) {
    throw bad("the header's " + std::to_string(frames) + " frames of " + std::to_string(n) + " robots and " +
              std::to_string(changes) + " state changes do not fill the body's " + std::to_string(raw_size) +
              " bytes");
  }
  std::vector<std::uint8_t> raw(raw_size);
  uLongf got = static_cast<uLongf>(raw_size);
  if (uncompress(raw.data(), &got, reinterpret_cast<const Bytef*>(bytes.data() + at + 8),
                 static_cast<uLong>(packed_size)) != Z_OK ||
      got != raw_size) {
    throw bad("corrupt body: zlib could not inflate it to the " + std::to_string(raw_size) +
              " bytes it declares");
  }

  ByteReader in(raw);
  r.frame_ticks.resize(frames);
  const std::size_t cells = frames * n;
  r.qx.resize(cells);
  r.qy.resize(cells);
  r.heading.resize(cells);
  r.led.resize(cells);
  r.state.resize(cells);
  r.parent.resize(cells);
  r.child.resize(cells);
  for (std::size_t f = 0; f < frames; ++f) {
    const std::size_t k0 = f * n;
    r.frame_ticks[f] = in.i32();
    if (f > 0 && r.frame_ticks[f] <= r.frame_ticks[f - 1]) throw bad("frame ticks do not increase");
    for (std::size_t i = 0; i < n; ++i)
      r.qx[k0 + i] = static_cast<std::uint16_t>(in.u16() + (f > 0 ? r.qx[k0 - n + i] : 0));
    for (std::size_t i = 0; i < n; ++i)
      r.qy[k0 + i] = static_cast<std::uint16_t>(in.u16() + (f > 0 ? r.qy[k0 - n + i] : 0));
    for (std::size_t i = 0; i < n; ++i) r.heading[k0 + i] = in.u8();
    for (std::size_t i = 0; i < n; ++i) {
      r.led[k0 + i] = in.u8();
      if (r.led[k0 + i] >= r.leds.size()) throw bad("a frame names an LED colour the header does not list");
    }
    for (std::size_t i = 0; i < n; ++i) r.state[k0 + i] = in.u8();
    for (std::size_t i = 0; i < n; ++i) r.parent[k0 + i] = in.i32();
    for (std::size_t i = 0; i < n; ++i) r.child[k0 + i] = in.i32();
  }
  r.changes.resize(changes);
  for (StateChange& c : r.changes) {
    c.tick = in.i32();
    c.robot = in.i32();
    c.from = in.u8();
    c.to = in.u8();
    c.pf_row = in.u8();
    c.ta_row = in.u8();
    if (c.robot < 0 || c.robot >= r.robots)
      throw bad("a state change names robot " + std::to_string(c.robot));
  }
  return r;
}

}  // namespace swarmpath::sim
