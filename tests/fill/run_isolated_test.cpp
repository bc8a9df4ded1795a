#include "blayer/fill/run_isolated.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "blayer/core/stopwatch.h"

namespace blayer {
namespace {

TEST(RunIsolated, ReturnsTheChildsResultBytes) {
  const std::string big(300000, 'x');  // larger than a pipe buffer
  const IsolatedOutcome o = run_isolated([&] { return big + std::string(1, '\0') + "end"; }, 10);
  ASSERT_EQ(o.kind, IsolatedOutcome::Kind::kOk);
  EXPECT_EQ(o.data, big + std::string(1, '\0') + "end");
}

TEST(RunIsolated, ChildMemoryChangesDoNotReachTheCaller) {
  int value = 1;
  run_isolated(
      [&] {
        value = 2;
        return std::string();
      },
      10);
  EXPECT_EQ(value, 1);
}

TEST(RunIsolated, ThrownIntIsReportedAsCode) {
  const IsolatedOutcome o = run_isolated([]() -> std::string { throw 3; }, 10);
  EXPECT_EQ(o.kind, IsolatedOutcome::Kind::kThrewInt);
  EXPECT_EQ(o.thrown_int, 3);
}

TEST(RunIsolated, ThrownExceptionIsReportedWithItsMessage) {
  const IsolatedOutcome o =
      run_isolated([]() -> std::string { throw std::runtime_error("bad facet"); }, 10);
  EXPECT_EQ(o.kind, IsolatedOutcome::Kind::kThrewException);
  EXPECT_EQ(o.data, "bad facet");
}

TEST(RunIsolated, SegfaultInChildBecomesErrorWithSignalNumber) {
  try {
    run_isolated(
        []() -> std::string {
          ::raise(SIGSEGV);
          return "unreachable";
        },
        10);
    FAIL() << "no exception";
  } catch (const ChildProcessError& e) {
    EXPECT_NE(std::string(e.what()).find("signal " + std::to_string(SIGSEGV)), std::string::npos)
        << e.what();
  }
}

TEST(RunIsolated, AbortInChildBecomesErrorAndCallerSurvives) {
  EXPECT_THROW(run_isolated([]() -> std::string { std::abort(); }, 10), ChildProcessError);
  EXPECT_EQ(run_isolated([] { return std::string("alive"); }, 10).data, "alive");
}

TEST(RunIsolated, ExitWithoutResultIsAnError) {
  EXPECT_THROW(run_isolated([]() -> std::string { ::_exit(0); }, 10), ChildProcessError);
}

TEST(RunIsolated, HangingChildIsKilledAtTheTimeout) {
  const Stopwatch clock;
  try {
    run_isolated(
        []() -> std::string {
          for (;;) ::pause();
        },
        0.3);
    FAIL() << "no exception";
  } catch (const ChildProcessError& e) {
    EXPECT_NE(std::string(e.what()).find("timed out"), std::string::npos) << e.what();
  }
  EXPECT_LT(clock.seconds(), 5.0);
}

TEST(RunIsolated, WorksWhileOtherThreadsRun) {
  std::atomic<bool> stop{false};
  std::thread busy([&] {
    while (!stop) std::this_thread::yield();
  });
  const IsolatedOutcome o = run_isolated([] { return std::string(1000, 'y'); }, 10);
  stop = true;
  busy.join();
  EXPECT_EQ(o.data.size(), 1000u);
}

}  // namespace
}  // namespace blayer
