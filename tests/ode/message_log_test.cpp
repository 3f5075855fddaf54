// wtc::ode::MessageLog: ODE's messages (dMessage) counted per log on the
// thread that captures, everything else passed to the handler that was
// there before, and that handler put back when the last log goes (ODE has
// one handler for the whole process).
#include "wtc/ode/message_log.hpp"

#include <gtest/gtest.h>
#include <ode/ode.h>

#include <string>
#include <thread>
#include <vector>

namespace wtc::ode {
namespace {

// ODE's own format (lcp.cpp) and number (d_ERR_LCP).
constexpr const char* kLcpFormat = "LCP internal error, s <= 0 (s=%.4e)";
constexpr int kLcpNumber = 3;

// A program's own handler, installed before any log: what reaches it.
std::vector<std::string> g_received;
extern "C" void programHandler(int, const char* format, va_list args) {
  char text[256];
  std::vsnprintf(text, sizeof text, format, args);
  g_received.emplace_back(text);
}

TEST(MessageLogTest, TextLeavesOutTheNumbersOfAMessage) {
  EXPECT_EQ(messageText(kLcpFormat), "LCP internal error, s <= 0");
  EXPECT_EQ(messageText("joint %d: bad axis (%g, %g, %g) in world"), "joint ...: bad axis in world");
  EXPECT_EQ(messageText("100%% sure at %5.2lf s"), "100% sure at ... s");
  EXPECT_EQ(messageText("no numbers (none)"), "no numbers (none)");
}

TEST(MessageLogTest, CountsTheMessagesOfTheStepsItCapturesAndPassesOnTheRest) {
  g_received.clear();
  dSetMessageHandler(&programHandler);
  {
    MessageLog log;
    // Case: a message outside any capture goes where it went before.
    dMessage(kLcpNumber, kLcpFormat, 0.0);
    EXPECT_EQ(g_received, std::vector<std::string>{"LCP internal error, s <= 0 (s=0.0000e+00)"});
    EXPECT_EQ(log.total(), 0u);
    // Case: inside a capture it is counted, by message, and not passed on.
    {
      const MessageLog::Capture capture(log);
      dMessage(kLcpNumber, kLcpFormat, -1.5e-17);
      dMessage(kLcpNumber, kLcpFormat, 0.0);
      dMessage(7, "something else (%d)", 4);
    }
    EXPECT_EQ(g_received.size(), 1u);
    EXPECT_EQ(log.total(), 3u);
    ASSERT_EQ(log.counts().size(), 2u);
    EXPECT_EQ(log.counts()[0].number, kLcpNumber);
    EXPECT_EQ(log.counts()[0].text, "LCP internal error, s <= 0");
    EXPECT_EQ(log.counts()[0].first, "LCP internal error, s <= 0 (s=-1.5000e-17)");
    EXPECT_EQ(log.counts()[0].count, 2u);
    EXPECT_EQ(log.counts()[1].text, "something else");
    EXPECT_EQ(log.counts()[1].count, 1u);
    // Case: nested captures: the innermost counts.
    MessageLog inner;
    {
      const MessageLog::Capture outer_capture(log);
      {
        const MessageLog::Capture inner_capture(inner);
        dMessage(kLcpNumber, kLcpFormat, 0.0);
      }
      dMessage(kLcpNumber, kLcpFormat, 0.0);
    }
    EXPECT_EQ(inner.total(), 1u);
    EXPECT_EQ(log.total(), 4u);
    // Case: a log that keeps the total alone (whether a solve gave up)
    // counts every message and keeps none of them.
    MessageLog total_only(MessageLog::Keep::kTotal);
    {
      const MessageLog::Capture capture(total_only);
      dMessage(kLcpNumber, kLcpFormat, 0.0);
      dMessage(7, "something else (%d)", 4);
    }
    EXPECT_EQ(total_only.total(), 2u);
    EXPECT_TRUE(total_only.counts().empty());
    EXPECT_EQ(g_received.size(), 1u);
  }
  // Case: the last log gone, the program's handler is ODE's again.
  EXPECT_EQ(dGetMessageHandler(), &programHandler);
  dMessage(kLcpNumber, kLcpFormat, 0.0);
  EXPECT_EQ(g_received.size(), 2u);
  dSetMessageHandler(nullptr);
}

// A solve tried in a log of its own and kept (wtc::ode_sim's direct step)
// is counted in the engine's log as if it had come there: merged by
// message, the first in full kept from the log it first came to; a solve
// dropped is forgotten.
TEST(MessageLogTest, ALogMergedIntoAnotherCountsThereAsIfItHadComeThere) {
  MessageLog engine_log, attempt;
  {
    const MessageLog::Capture capture(engine_log);
    dMessage(kLcpNumber, kLcpFormat, -1.5e-17);
  }
  {
    const MessageLog::Capture capture(attempt);
    dMessage(kLcpNumber, kLcpFormat, 0.0);
    dMessage(7, "something else (%d)", 4);
  }
  engine_log.merge(attempt);
  EXPECT_EQ(engine_log.total(), 3u);
  ASSERT_EQ(engine_log.counts().size(), 2u);
  EXPECT_EQ(engine_log.counts()[0].count, 2u);
  EXPECT_EQ(engine_log.counts()[0].first, "LCP internal error, s <= 0 (s=-1.5000e-17)");
  EXPECT_EQ(engine_log.counts()[1].text, "something else");
  EXPECT_EQ(engine_log.counts()[1].first, "something else (4)");
  // Case: a message merged in is found again by its format when it comes.
  {
    const MessageLog::Capture capture(engine_log);
    dMessage(7, "something else (%d)", 5);
  }
  EXPECT_EQ(engine_log.counts().size(), 2u);
  EXPECT_EQ(engine_log.counts()[1].count, 2u);
  // Case: cleared, a log has nothing, and counts afresh.
  attempt.clear();
  EXPECT_EQ(attempt.total(), 0u);
  EXPECT_TRUE(attempt.counts().empty());
  {
    const MessageLog::Capture capture(attempt);
    dMessage(kLcpNumber, kLcpFormat, 0.0);
  }
  ASSERT_EQ(attempt.counts().size(), 1u);
  EXPECT_EQ(attempt.counts()[0].first, "LCP internal error, s <= 0 (s=0.0000e+00)");
}

TEST(MessageLogTest, WithoutAHandlerBeforeItPrintsAsOdeAndRestoresNone) {
  dSetMessageHandler(nullptr);
  {
    MessageLog log;
    ::testing::internal::CaptureStderr();
    dMessage(kLcpNumber, kLcpFormat, 0.0);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "\nODE Message 3: LCP internal error, s <= 0 (s=0.0000e+00)\n");
  }
  EXPECT_EQ(dGetMessageHandler(), nullptr);
}

TEST(MessageLogTest, EachThreadCountsIntoItsOwnLog) {
  constexpr int kThreads = 4, kMessages = 1000;
  std::vector<std::unique_ptr<MessageLog>> logs;
  for (int t = 0; t < kThreads; ++t) logs.push_back(std::make_unique<MessageLog>());
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      const MessageLog::Capture capture(*logs[t]);
      for (int k = 0; k < kMessages * (t + 1); ++k) dMessage(kLcpNumber, kLcpFormat, 0.0);
    });
  }
  for (std::thread& t : threads) t.join();
  for (int t = 0; t < kThreads; ++t) {
    EXPECT_EQ(logs[t]->total(), static_cast<std::uint64_t>(kMessages * (t + 1)));
    ASSERT_EQ(logs[t]->counts().size(), 1u);
    EXPECT_EQ(logs[t]->counts()[0].count, static_cast<std::uint64_t>(kMessages * (t + 1)));
  }
}

}  // namespace
}  // namespace wtc::ode
