#include "accsim/scenarios/llm_extractor.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

namespace accsim {
namespace {

// A minimal OpenAI-compatible chat server on 127.0.0.1 and an ephemeral
// port. It answers every completion with `content` and stops when the test
// ends (destructor), or by itself after kLifetime should a test hang.
class FakeChatServer {
 public:
  explicit FakeChatServer(std::string content, int status = 200) : content_(std::move(content)), status_(status) {
    server_.Post("/v1/chat/completions", [this](const httplib::Request& req, httplib::Response& res) {
      last_request_ = req.body;
      ++requests_;
      if (status_ != 200) {
        res.status = status_;
        res.set_content("model not loaded", "text/plain");
        return;
      }
      const nlohmann::json reply = {
          {"id", "chatcmpl-test"},
          {"object", "chat.completion"},
          {"choices", {{{"index", 0}, {"message", {{"role", "assistant"}, {"content", content_}}}, {"finish_reason", "stop"}}}}};
      res.set_content(reply.dump(), "application/json");
    });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    watchdog_ = std::thread([this] {
      const auto until = std::chrono::steady_clock::now() + kLifetime;
      while (!done_ && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      server_.stop();
    });
    // The socket listens from bind_to_any_port on: early requests wait in its backlog.
  }
  ~FakeChatServer() {
    done_ = true;
    watchdog_.join();
    thread_.join();
  }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  const std::string& last_request() const { return last_request_; }
  int requests() const { return requests_; }

 private:
  static constexpr std::chrono::seconds kLifetime{60};
  httplib::Server server_;
  std::string content_;
  int status_;
  int port_ = 0;
  std::string last_request_;
  std::atomic<int> requests_{0};
  std::atomic<bool> done_{false};
  std::thread thread_, watchdog_;
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
                                 {"vehicles", {{{"movement", "flying"}}}}};
  EXPECT_EQ(MergeLlmAnswer(answer, r), 1);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  std::string all;
  for (const auto& w : r.warnings) all += w + "\n";
  EXPECT_NE(all.find("lanes_total"), std::string::npos) << all;
  EXPECT_NE(all.find("surface"), std::string::npos) << all;
  EXPECT_NE(all.find("speed_limit.unit"), std::string::npos) << all;
  EXPECT_NE(all.find("vehicles[0].movement"), std::string::npos) << all;
  EXPECT_EQ(r.road.lanes_total.source, Provenance::kDefaulted);
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
