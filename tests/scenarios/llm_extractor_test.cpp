#include "accsim/scenarios/llm_extractor.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace accsim {
namespace {

// A minimal OpenAI-compatible chat server on 127.0.0.1 and an ephemeral
// port, over plain sockets. It answers every completion with `content`
// (HTTP `status`) and stops when the test ends, or by itself after
// kLifetime should a test hang.
class FakeChatServer {
 public:
  explicit FakeChatServer(std::string content, int status = 200) : content_(std::move(content)), status_(status) {
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    if (listen_fd_ < 0 || ::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0 ||
        ::listen(listen_fd_, 8) != 0) {
      throw std::runtime_error("test server: cannot listen on 127.0.0.1");
    }
    socklen_t len = sizeof(addr);
    ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    thread_ = std::thread([this] { Serve(); });
  }
  ~FakeChatServer() {
    done_ = true;
    thread_.join();
    ::close(listen_fd_);
  }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  std::string last_request() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_request_;
  }
  std::string last_path() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_path_;
  }
  int requests() const { return requests_; }

 private:
  static constexpr std::chrono::seconds kLifetime{60};

  void Serve() {
    const auto until = std::chrono::steady_clock::now() + kLifetime;
    while (!done_ && std::chrono::steady_clock::now() < until) {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 20) != 1) continue;
      const int fd = ::accept(listen_fd_, nullptr, nullptr);
      if (fd < 0) continue;
      Handle(fd);
      ::close(fd);
    }
  }

  void Handle(int fd) {
    std::string in;
    char buf[4096];
    size_t head_end = std::string::npos, need = 0;
    while (true) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 2000) != 1) return;
      const ssize_t n = ::recv(fd, buf, sizeof(buf), 0);
      if (n <= 0) return;
      in.append(buf, static_cast<size_t>(n));
      if (head_end == std::string::npos && (head_end = in.find("\r\n\r\n")) != std::string::npos) {
        const size_t cl = in.find("Content-Length: ");
        need = cl < head_end ? std::stoul(in.substr(cl + 16)) : 0;
      }
      if (head_end != std::string::npos && in.size() >= head_end + 4 + need) break;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last_path_ = in.substr(5, in.find(' ', 5) - 5);
      last_request_ = in.substr(head_end + 4, need);
    }
    ++requests_;
    std::string body;
    if (status_ == 200) {
      const nlohmann::json reply = {
          {"id", "chatcmpl-test"},
          {"object", "chat.completion"},
          {"choices",
           {{{"index", 0}, {"message", {{"role", "assistant"}, {"content", content_}}}, {"finish_reason", "stop"}}}}};
      body = reply.dump();
    } else {
      body = "model not loaded";
    }
    const std::string out = "HTTP/1.1 " + std::to_string(status_) + " X\r\nContent-Type: application/json\r\n" +
                            "Content-Length: " + std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body;
    ::send(fd, out.data(), out.size(), MSG_NOSIGNAL);
  }

  std::string content_;
  int status_;
  int listen_fd_ = -1;
  int port_ = 0;
  mutable std::mutex mutex_;
  std::string last_request_, last_path_;
  std::atomic<int> requests_{0};
  std::atomic<bool> done_{false};
  std::thread thread_;
};

const char* kNarrative =
    "V1, a 2001 Toyota Camry, was traveling east. V2 was traveling north. The front of V2 struck the left side of V1.";

TEST(LlmExtractorTest, SpeaksTheChatProtocolAndMergesFieldByField) {
  // The model fills what the text left open (limit, lanes) and disagrees on
  // a stated direction, which the rules keep.
  FakeChatServer server(
      "```json\n{\"speed_limit\": {\"value\": 56, \"unit\": \"km/h\"}, \"lanes_total\": 4, \"divided\": false, "
      "\"participant_count\": 2, \"vehicles\": [{\"id\": \"V1\", \"class\": \"car\", \"travel\": \"west\", "
      "\"movement\": \"going_straight\"}, {\"id\": \"V2\", \"class\": \"suv\", \"movement\": \"going_straight\"}], "
      "\"crash_type\": \"angle\", \"location\": \"junction\"}\n```");
  LlmConfig config;
  config.url = server.url();
  config.model = "test-model";
  config.timeout_s = 10;
  const AccidentRecord r = LlmExtractor(config).Extract(kNarrative);
  EXPECT_EQ(server.requests(), 1);
  EXPECT_EQ(server.last_path(), "/v1/chat/completions");
  const nlohmann::json request = nlohmann::json::parse(server.last_request());
  EXPECT_EQ(request["model"], "test-model");
  EXPECT_EQ(request["temperature"], 0);
  ASSERT_TRUE(request["messages"].is_array());
  EXPECT_EQ(request["messages"].front()["role"], "system");
  EXPECT_EQ(request["messages"].back()["content"], kNarrative);  // few-shot examples come before it

  EXPECT_NEAR(r.road.speed_limit_mps.value * 3.6, 56.0, 1e-9);
  EXPECT_EQ(r.road.speed_limit_mps.source, Provenance::kInferred);
  EXPECT_EQ(r.road.speed_limit_unit.value, "km/h");
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kEast);  // stated by the text: kept
  EXPECT_EQ(r.vehicles[0].travel.source, Provenance::kStated);
  EXPECT_EQ(r.vehicles[1].vehicle_class.value, VehicleClass::kSuv);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
  bool disagreement = false;
  for (const auto& w : r.warnings) disagreement |= w.find("vehicles[0].travel") != std::string::npos;
  EXPECT_TRUE(disagreement);
}

TEST(LlmExtractorTest, InvalidFieldsAreDroppedWithAWarningNamingThem) {
  AccidentRecord r;
  r.vehicles.resize(2);
  const nlohmann::json answer = {{"lanes_total", -3},
                                 {"surface", "lava"},
                                 {"speed_limit", {{"value", 50}, {"unit", "furlongs"}}},
                                 {"crash_type", "rear_end"},
                                 {"vehicles", {{{"movement", "flying"}, {"pre_event_movement", "hovering"}}}}};
  EXPECT_EQ(MergeLlmAnswer(answer, r), 1);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  std::string all;
  for (const auto& w : r.warnings) all += w + "\n";
  EXPECT_NE(all.find("lanes_total"), std::string::npos) << all;
  EXPECT_NE(all.find("surface"), std::string::npos) << all;
  EXPECT_NE(all.find("speed_limit.unit"), std::string::npos) << all;
  EXPECT_NE(all.find("vehicles[0].movement"), std::string::npos) << all;
  EXPECT_NE(all.find("vehicles[0].pre_event_movement"), std::string::npos) << all;
  EXPECT_EQ(r.road.lanes_total.source, Provenance::kDefaulted);
}

TEST(LlmExtractorTest, PreEventMovementFillsWhatTheRulesOnlyInferred) {
  AccidentRecord r;
  r.vehicles.resize(1);
  r.vehicles[0].pre_event.Set(Movement::kStraight, Provenance::kInferred);
  EXPECT_EQ(MergeLlmAnswer({{"vehicles", {{{"pre_event_movement", "stopped"}}}}}, r), 1);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[0].pre_event.source, Provenance::kInferred);
}

TEST(LlmExtractorTest, ServerFailuresFallBackToTheRules) {
  {
    FakeChatServer server("no json here at all");
    LlmConfig config;
    config.url = server.url();
    const AccidentRecord r = LlmExtractor(config).Extract(kNarrative);
    EXPECT_EQ(r.crash.striking.value, "V2");  // the rules' answer
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings.back().find("no JSON object"), std::string::npos) << r.warnings.back();
  }
  {
    FakeChatServer server("{}", 503);
    LlmConfig config;
    config.url = server.url() + "/v1";
    EXPECT_THROW(LlmExtractor(config).Ask(kNarrative), std::runtime_error);
  }
  // Nothing listens on port 9 of the loopback: a clear error, quickly.
  LlmConfig config;
  config.url = "http://127.0.0.1:9";
  config.timeout_s = 2;
  try {
    LlmExtractor(config).Ask(kNarrative);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no answer"), std::string::npos) << e.what();
  }
}

TEST(LlmExtractorTest, ConfigErrorsNameTheField) {
  const auto message = [](LlmConfig c) {
    try {
      Validate(c);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  LlmConfig c;
  c.url = "ftp://x";
  EXPECT_NE(message(c).find("llm.url"), std::string::npos);
  c = LlmConfig{};
  c.url = "https://api.example.com";
  EXPECT_NE(message(c).find("https"), std::string::npos);
  c = LlmConfig{};
  c.timeout_s = 0;
  EXPECT_NE(message(c).find("llm.timeout_s"), std::string::npos);
  c = LlmConfig{};
  c.model = "";
  EXPECT_NE(message(c).find("llm.model"), std::string::npos);
  EXPECT_EQ(message(LlmConfig{}), "");
}

}  // namespace
}  // namespace accsim
