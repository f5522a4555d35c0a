#include "accsim/scenarios/llm_extractor.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>

namespace accsim {
namespace {

constexpr double kMphToMps = 0.44704;
constexpr double kKmhToMps = 1.0 / 3.6;
// Narratives longer than this are cut before they reach the model (a
// local model's context is small; the crash is described first).
constexpr size_t kMaxPromptChars = 12000;

struct Endpoint {
  std::string host;
  std::string port = "80";
  std::string path;  // "/v1/chat/completions"
};

Endpoint ParseUrl(const std::string& url) {
  if (url.rfind("https://", 0) == 0) {
    throw std::invalid_argument("llm.url: https is not supported; the model server is expected on this machine (http)");
  }
  if (url.rfind("http://", 0) != 0) throw std::invalid_argument("llm.url: must start with http:// (got '" + url + "')");
  const size_t slash = url.find('/', 7);
  const std::string authority = url.substr(7, slash == std::string::npos ? std::string::npos : slash - 7);
  Endpoint e;
  const size_t colon = authority.rfind(':');
  e.host = colon == std::string::npos ? authority : authority.substr(0, colon);
  if (colon != std::string::npos) e.port = authority.substr(colon + 1);
  if (!e.host.empty() && e.host.front() == '[' && e.host.back() == ']') e.host = e.host.substr(1, e.host.size() - 2);
  if (e.host.empty()) throw std::invalid_argument("llm.url: no host in '" + url + "'");
  if (e.port.empty() || e.port.size() > 5 || e.port.find_first_not_of("0123456789") != std::string::npos ||
      std::stoi(e.port) < 1 || std::stoi(e.port) > 65535) {
    throw std::invalid_argument("llm.url: bad port in '" + url + "'");
  }
  std::string path = slash == std::string::npos ? "" : url.substr(slash);
  while (!path.empty() && path.back() == '/') path.pop_back();
  if (path.size() >= 17 && path.compare(path.size() - 17, 17, "/chat/completions") == 0) {
    e.path = path;
  } else if (path.size() >= 3 && path.compare(path.size() - 3, 3, "/v1") == 0) {
    e.path = path + "/chat/completions";
  } else {
    e.path = path + "/v1/chat/completions";
  }
  return e;
}

// A socket closed on every path out.
class Socket {
 public:
  explicit Socket(int fd) : fd_(fd) {}
  ~Socket() {
    if (fd_ >= 0) ::close(fd_);
  }
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

struct HttpReply {
  int status = 0;
  std::string body;
};

// One HTTP/1.1 POST with "Connection: close" (plain HTTP, as local model
// servers speak it), bounded by one deadline for connect, send and receive.
// A few dozen lines of sockets keep the library free of a client dependency.
HttpReply HttpPost(const Endpoint& e, const std::string& body, const std::string& api_key, double timeout_s) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  const auto remaining_ms = [&]() {
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return static_cast<int>(std::max<long long>(0, std::min<long long>(ms, 1 << 30)));
  };
  const std::string where = "http://" + e.host + ":" + e.port + e.path;
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(e.host.c_str(), e.port.c_str(), &hints, &found); rc != 0 || !found) {
    throw std::runtime_error("llm: no answer from " + where + " (cannot resolve host: " + ::gai_strerror(rc) + ")");
  }
  std::string error = "connection refused";
  int connected = -1;
  for (addrinfo* ai = found; ai && connected < 0; ai = ai->ai_next) {
    const int fd = ::socket(ai->ai_family, ai->ai_socktype | SOCK_CLOEXEC, ai->ai_protocol);
    if (fd < 0) continue;
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL, 0) | O_NONBLOCK);
    int rc = ::connect(fd, ai->ai_addr, ai->ai_addrlen);
    if (rc != 0 && errno == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      int so_error = ETIMEDOUT;
      if (::poll(&p, 1, remaining_ms()) == 1) {
        socklen_t len = sizeof(so_error);
        ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &so_error, &len);
      }
      rc = so_error == 0 ? 0 : -1;
      if (rc != 0) error = std::strerror(so_error);
    } else if (rc != 0) {
      error = std::strerror(errno);
    }
    if (rc == 0) {
      connected = fd;
    } else {
      ::close(fd);
    }
  }
  ::freeaddrinfo(found);
  if (connected < 0) throw std::runtime_error("llm: no answer from " + where + " (" + error + ")");
  const Socket sock(connected);
  const int fd = sock.fd();

  std::string request = "POST " + e.path + " HTTP/1.1\r\nHost: " + e.host + ":" + e.port +
                        "\r\nContent-Type: application/json\r\nAccept: application/json\r\nContent-Length: " +
                        std::to_string(body.size()) + "\r\nConnection: close\r\n";
  if (!api_key.empty()) request += "Authorization: Bearer " + api_key + "\r\n";
  request += "\r\n" + body;
  size_t sent = 0;
  while (sent < request.size()) {
    pollfd p{fd, POLLOUT, 0};
    if (::poll(&p, 1, remaining_ms()) != 1) throw std::runtime_error("llm: timed out sending to " + where);
    const ssize_t n = ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) throw std::runtime_error("llm: no answer from " + where + " (send failed: " + std::strerror(errno) + ")");
    sent += static_cast<size_t>(n);
  }
  constexpr size_t kMaxReply = 16u << 20;  // a chat answer is kilobytes
  std::string raw;
  char buf[8192];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, remaining_ms());
    if (ready != 1) throw std::runtime_error("llm: timed out waiting for " + where);
    const ssize_t n = ::recv(fd, buf, sizeof(buf), 0);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    if (n < 0) throw std::runtime_error("llm: no answer from " + where + " (" + std::strerror(errno) + ")");
    if (n == 0) break;
    raw.append(buf, static_cast<size_t>(n));
    if (raw.size() > kMaxReply) throw std::runtime_error("llm: the reply from " + where + " is larger than 16 MB");
  }
  const size_t head_end = raw.find("\r\n\r\n");
  if (raw.rfind("HTTP/", 0) != 0 || head_end == std::string::npos) {
    throw std::runtime_error("llm: " + where + " did not answer with HTTP");
  }
  HttpReply reply;
  const size_t sp = raw.find(' ');
  reply.status = sp != std::string::npos && sp < head_end ? std::atoi(raw.c_str() + sp + 1) : 0;
  std::string head = raw.substr(0, head_end);
  for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string payload = raw.substr(head_end + 4);
  if (head.find("transfer-encoding: chunked") != std::string::npos) {
    std::string joined;
    size_t at = 0;
    while (at < payload.size()) {
      const size_t eol = payload.find("\r\n", at);
      if (eol == std::string::npos) break;
      const unsigned long size = std::strtoul(payload.substr(at, eol - at).c_str(), nullptr, 16);
      if (size == 0 || eol + 2 + size > payload.size()) break;
      joined += payload.substr(eol + 2, size);
      at = eol + 2 + size + 2;
    }
    payload = std::move(joined);
  }
  reply.body = std::move(payload);
  return reply;
}

const char* kSchema = R"({
  "road_kind": "straight|curve|intersection|t_junction|ramp|driveway",
  "lanes_total": <int, lanes of V1's road in both directions, or null>,
  "lanes_per_direction": <int or null>,
  "divided": <bool or null>, "one_way": <bool or null>,
  "speed_limit": {"value": <number>, "unit": "mph|km/h"} or null,
  "surface": "dry|wet|snow|ice" or null,
  "participant_count": <int>,
  "vehicles": [{"id": "V1", "class": "car|suv|pickup|van|truck|bus|motorcycle",
                "travel": "north|south|east|west" or null,
                "movement": "going_straight|turning_left|turning_right|changing_lanes|stopped|slowing|backing|passing|merging",
                "pre_event_movement": <same values as movement>,
                "speed": {"value": <number>, "unit": "mph|km/h"} or null}],
  "crash_type": "rear_end|head_on|angle|sideswipe_same_direction|sideswipe_opposite_direction|turn_across_path|turn_into_path|single_vehicle",
  "striking": "V1", "struck": "V2" or "object",
  "striking_area": "front|rear|left|right", "struck_area": "front|rear|left|right",
  "location": "junction|segment|driveway|ramp"
})";

const char* kExample1 =
    "V1, a 2004 Ford F-150 pickup, was northbound on a two-lane undivided road with a posted limit of 35 mph. "
    "V2, a 1999 Honda Civic, was stopped ahead waiting to turn left into a driveway. The front of V1 struck the "
    "back of V2. The driver of V2 was transported to a hospital.";
const char* kAnswer1 =
    R"({"road_kind":"driveway","lanes_total":2,"lanes_per_direction":1,"divided":false,"one_way":false,)"
    R"("speed_limit":{"value":35,"unit":"mph"},"surface":null,"participant_count":2,"vehicles":[)"
    R"({"id":"V1","class":"pickup","travel":"north","movement":"going_straight","pre_event_movement":"going_straight","speed":null},)"
    R"({"id":"V2","class":"car","travel":"north","movement":"stopped","pre_event_movement":"stopped","speed":null}],)"
    R"("crash_type":"rear_end","striking":"V1","struck":"V2","striking_area":"front","struck_area":"rear","location":"driveway"})";
const char* kExample2 =
    "Vehicle #1, a Jeep Cherokee, was traveling west and turned left at the four-leg intersection. Vehicle #2, a "
    "Toyota Camry, was eastbound at about 40 mph. The wet road had a speed limit of 72 km/h. Vehicle #1 was struck "
    "in the right side by the front of Vehicle #2.";
const char* kAnswer2 =
    R"({"road_kind":"intersection","lanes_total":null,"lanes_per_direction":null,"divided":null,"one_way":null,)"
    R"("speed_limit":{"value":72,"unit":"km/h"},"surface":"wet","participant_count":2,"vehicles":[)"
    R"({"id":"V1","class":"suv","travel":"west","movement":"turning_left","pre_event_movement":"turning_left","speed":null},)"
    R"({"id":"V2","class":"car","travel":"east","movement":"going_straight","pre_event_movement":"going_straight","speed":{"value":40,"unit":"mph"}}],)"
    R"("crash_type":"turn_across_path","striking":"V2","struck":"V1","striking_area":"front","struck_area":"right","location":"junction"})";

// Pulls the JSON object out of a model's reply (models like ```json fences).
nlohmann::json ParseAnswer(const std::string& content) {
  const size_t a = content.find('{');
  const size_t b = content.rfind('}');
  if (a == std::string::npos || b == std::string::npos || b < a) {
    throw std::runtime_error("llm: the reply holds no JSON object");
  }
  try {
    nlohmann::json j = nlohmann::json::parse(content.substr(a, b - a + 1));
    if (!j.is_object()) throw std::runtime_error("llm: the reply is not a JSON object");
    return j;
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(std::string("llm: the reply is not valid JSON (") + e.what() + ")");
  }
}

std::optional<double> SpeedMps(const nlohmann::json& s, const std::string& field, std::vector<std::string>& warn,
                               std::string* unit_out) {
  if (s.is_null()) return std::nullopt;
  if (!s.is_object() || !s.contains("value") || !s["value"].is_number() || !s.contains("unit") ||
      !s["unit"].is_string()) {
    warn.push_back("llm: " + field + ": expected {\"value\": number, \"unit\": \"mph\"|\"km/h\"}; ignored");
    return std::nullopt;
  }
  const double v = s["value"].get<double>();
  const std::string unit = s["unit"].get<std::string>();
  if (unit != "mph" && unit != "km/h") {
    warn.push_back("llm: " + field + ".unit: '" + unit + "' is neither mph nor km/h; ignored");
    return std::nullopt;
  }
  if (!std::isfinite(v) || v <= 0 || v > 200) {
    warn.push_back("llm: " + field + ".value: out of range (0, 200]; ignored");
    return std::nullopt;
  }
  if (unit_out) *unit_out = unit;
  return v * (unit == "mph" ? kMphToMps : kKmhToMps);
}

// Takes a model value unless the rules stated a value of their own.
template <typename T>
bool Take(Field<T>& f, T v, const std::string& field, std::vector<std::string>& warn) {
  if (f.source == Provenance::kStated) {
    if (!(f.value == v)) warn.push_back("llm: " + field + ": the model disagrees with the text's stated value; kept");
    return false;
  }
  f.Set(std::move(v), Provenance::kInferred);
  return true;
}

}  // namespace

void Validate(const LlmConfig& c) {
  (void)ParseUrl(c.url);
  if (c.model.empty()) throw std::invalid_argument("llm.model: must not be empty");
  if (!(c.timeout_s > 0.0 && c.timeout_s <= 3600.0)) throw std::invalid_argument("llm.timeout_s: must be in (0, 3600]");
  if (c.max_tokens < 64 || c.max_tokens > 32768) throw std::invalid_argument("llm.max_tokens: must be in [64, 32768]");
}

nlohmann::json BuildLlmMessages(std::string_view narrative) {
  const std::string system =
      std::string("You read police and NHTSA crash narratives and answer with one JSON object only, no prose. ") +
      "Vehicles are V1, V2, ... in the order the report numbers them. Use null for anything the text does not say. "
      "Ignore injury, medical and interview details. lanes_total counts V1's road in both directions. "
      "movement is the manoeuvre each vehicle made into the crash (a vehicle that stopped at a sign and then "
      "turned left is turning_left; one still stopped is stopped); pre_event_movement is what it did before the "
      "critical event, as NASS codes it (that turning vehicle is stopped). Schema:\n" +
      kSchema;
  std::string text(narrative.substr(0, kMaxPromptChars));
  return nlohmann::json::array({{{"role", "system"}, {"content", system}},
                                {{"role", "user"}, {"content", kExample1}},
                                {{"role", "assistant"}, {"content", kAnswer1}},
                                {{"role", "user"}, {"content", kExample2}},
                                {{"role", "assistant"}, {"content", kAnswer2}},
                                {{"role", "user"}, {"content", text}}});
}

int MergeLlmAnswer(const nlohmann::json& a, AccidentRecord& r) {
  int taken = 0;
  std::vector<std::string>& warn = r.warnings;
  if (!a.is_object()) {
    warn.push_back("llm: answer: not a JSON object; ignored");
    return 0;
  }
  // Each field on its own: a bad value drops that field only.
  auto with = [&](const char* key, auto&& fn) {
    if (!a.contains(key) || a[key].is_null()) return;
    try {
      taken += fn(a[key]) ? 1 : 0;
    } catch (const std::exception& e) {
      warn.push_back(std::string("llm: ") + key + ": " + e.what() + "; ignored");
    }
  };
  auto count = [](const nlohmann::json& v, int lo, int hi) {
    if (!v.is_number_integer()) throw std::invalid_argument("expected an integer");
    const int n = v.get<int>();
    if (n < lo || n > hi) throw std::invalid_argument("out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return n;
  };
  auto boolean = [](const nlohmann::json& v) {
    if (!v.is_boolean()) throw std::invalid_argument("expected true or false");
    return v.get<bool>();
  };
  auto text = [](const nlohmann::json& v) {
    if (!v.is_string()) throw std::invalid_argument("expected a string");
    return v.get<std::string>();
  };
  with("road_kind", [&](const nlohmann::json& v) { return Take(r.road.kind, RoadKindFromString(text(v)), "road_kind", warn); });
  with("lanes_total", [&](const nlohmann::json& v) { return Take(r.road.lanes_total, count(v, 1, 16), "lanes_total", warn); });
  with("lanes_per_direction", [&](const nlohmann::json& v) {
    return Take(r.road.lanes_per_direction, count(v, 1, 8), "lanes_per_direction", warn);
  });
  with("divided", [&](const nlohmann::json& v) { return Take(r.road.divided, boolean(v), "divided", warn); });
  with("one_way", [&](const nlohmann::json& v) { return Take(r.road.one_way, boolean(v), "one_way", warn); });
  with("speed_limit", [&](const nlohmann::json& v) {
    std::string unit;
    const auto mps = SpeedMps(v, "speed_limit", warn, &unit);
    if (!mps) return false;
    if (r.road.speed_limit_mps.source == Provenance::kStated) {
      if (std::abs(r.road.speed_limit_mps.value - *mps) > 1.0) {
        warn.push_back("llm: speed_limit: the model disagrees with the text's stated value; kept");
      }
      return false;
    }
    r.road.speed_limit_mps.Set(*mps, Provenance::kInferred);
    r.road.speed_limit_unit.Set(unit, Provenance::kInferred);
    return true;
  });
  with("surface", [&](const nlohmann::json& v) { return Take(r.road.surface, SurfaceFromString(text(v)), "surface", warn); });
  with("participant_count", [&](const nlohmann::json& v) {
    return Take(r.participant_count, count(v, 1, 9), "participant_count", warn);
  });
  if (a.contains("vehicles") && a["vehicles"].is_array()) {
    const nlohmann::json& vs = a["vehicles"];
    for (size_t i = 0; i < vs.size() && i < 9; ++i) {
      const nlohmann::json& vj = vs[i];
      const std::string p = "vehicles[" + std::to_string(i) + "]";
      if (!vj.is_object()) {
        warn.push_back("llm: " + p + ": not an object; ignored");
        continue;
      }
      while (r.vehicles.size() <= i) {
        VehicleRecord nv;
        nv.id = "V" + std::to_string(r.vehicles.size() + 1);
        r.vehicles.push_back(nv);
      }
      VehicleRecord& v = r.vehicles[i];
      auto field = [&](const char* key, auto&& fn) {
        if (!vj.contains(key) || vj[key].is_null()) return;
        try {
          taken += fn(vj[key]) ? 1 : 0;
        } catch (const std::exception& e) {
          warn.push_back("llm: " + p + "." + key + ": " + e.what() + "; ignored");
        }
      };
      field("class", [&](const nlohmann::json& x) {
        return Take(v.vehicle_class, VehicleClassFromString(text(x)), p + ".class", warn);
      });
      field("travel", [&](const nlohmann::json& x) {
        return Take(v.travel, std::optional<Compass>(CompassFromString(text(x))), p + ".travel", warn);
      });
      field("movement", [&](const nlohmann::json& x) {
        return Take(v.movement, MovementFromString(text(x)), p + ".movement", warn);
      });
      field("pre_event_movement", [&](const nlohmann::json& x) {
        return Take(v.pre_event, MovementFromString(text(x)), p + ".pre_event_movement", warn);
      });
      field("speed", [&](const nlohmann::json& x) {
        std::string unit;
        const auto mps = SpeedMps(x, p + ".speed", warn, &unit);
        if (!mps || v.speed_mps.source == Provenance::kStated) return false;
        v.speed_mps.Set(*mps, Provenance::kInferred);
        v.speed_unit.Set(unit, Provenance::kInferred);
        return true;
      });
    }
  } else if (a.contains("vehicles")) {
    warn.push_back("llm: vehicles: expected an array; ignored");
  }
  auto vehicle_id = [&](const nlohmann::json& v, bool allow_object) {
    const std::string id = text(v);
    if (allow_object && id == "object") return id;
    if (id.size() == 2 && id[0] == 'V' && id[1] >= '1' && id[1] <= '9') return id;
    throw std::invalid_argument("expected V1..V9" + std::string(allow_object ? " or object" : ""));
  };
  with("crash_type", [&](const nlohmann::json& v) { return Take(r.crash.type, CrashTypeFromString(text(v)), "crash_type", warn); });
  with("striking", [&](const nlohmann::json& v) { return Take(r.crash.striking, vehicle_id(v, false), "striking", warn); });
  with("struck", [&](const nlohmann::json& v) { return Take(r.crash.struck, vehicle_id(v, true), "struck", warn); });
  with("striking_area", [&](const nlohmann::json& v) {
    return Take(r.crash.striking_area, DamageAreaFromString(text(v)), "striking_area", warn);
  });
  with("struck_area", [&](const nlohmann::json& v) {
    return Take(r.crash.struck_area, DamageAreaFromString(text(v)), "struck_area", warn);
  });
  with("location", [&](const nlohmann::json& v) {
    return Take(r.crash.location, CrashLocationFromString(text(v)), "location", warn);
  });
  return taken;
}

LlmExtractor::LlmExtractor(LlmConfig config) : config_(std::move(config)) { Validate(config_); }

nlohmann::json LlmExtractor::Ask(std::string_view narrative) const {
  const Endpoint e = ParseUrl(config_.url);
  const nlohmann::json body = {{"model", config_.model},
                               {"messages", BuildLlmMessages(narrative)},
                               {"temperature", 0},
                               {"max_tokens", config_.max_tokens},
                               {"stream", false},
                               {"response_format", {{"type", "json_object"}}}};
  const HttpReply res = HttpPost(e, body.dump(), config_.api_key, config_.timeout_s);
  if (res.status != 200) {
    throw std::runtime_error("llm: " + config_.url + e.path + " answered HTTP " + std::to_string(res.status) + ": " +
                             res.body.substr(0, 200));
  }
  nlohmann::json reply;
  try {
    reply = nlohmann::json::parse(res.body);
  } catch (const nlohmann::json::parse_error&) {
    throw std::runtime_error("llm: the server's reply is not JSON");
  }
  if (!reply.is_object() || !reply.contains("choices") || !reply["choices"].is_array() || reply["choices"].empty() ||
      !reply["choices"][0].is_object() || !reply["choices"][0].contains("message") ||
      !reply["choices"][0]["message"].is_object() || !reply["choices"][0]["message"].contains("content") ||
      !reply["choices"][0]["message"]["content"].is_string()) {
    throw std::runtime_error("llm: the reply has no choices[0].message.content (is this an OpenAI-compatible server?)");
  }
  return ParseAnswer(reply["choices"][0]["message"]["content"].get<std::string>());
}

AccidentRecord LlmExtractor::Extract(std::string_view text) const {
  AccidentRecord r = rules_.Extract(text);
  try {
    MergeLlmAnswer(Ask(text), r);
  } catch (const std::exception& e) {
    r.warnings.push_back(std::string(e.what()) + "; the record comes from the rules alone");
  }
  return r;
}

}  // namespace accsim
