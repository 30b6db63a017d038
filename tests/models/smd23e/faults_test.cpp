// Fault variants: each is selectable by name and differs observably from the correct model.
#include "tests/models/smd23e/smd23e_fixture.hpp"

namespace hilrig::models::smd23e::test {
namespace {

TEST(Smd23eFaultNames, EveryVariantRoundTripsByName) {
  const auto names = fault_names();
  ASSERT_EQ(names.size(), 4U);
  for (std::string_view n : names) {
    const auto f = fault_from_name(n);
    ASSERT_TRUE(f.has_value()) << n;
    EXPECT_EQ(fault_name(*f), n);
  }
  EXPECT_EQ(fault_from_name("wrong-acceleration"), Fault::WrongAcceleration);
  EXPECT_EQ(fault_from_name("lost-steps"), Fault::LostSteps);
  EXPECT_EQ(fault_from_name("ignored-limit"), Fault::IgnoredLimit);
  EXPECT_EQ(fault_from_name("late-stop"), Fault::LateStop);
  EXPECT_FALSE(fault_from_name("no-such-fault").has_value());
}

// One bench per variant; the scenario is the same, the correct model is the reference.
class Smd23eVariant : public Smd23eBench {
protected:
  explicit Smd23eVariant(Fault f) : Smd23eBench(Params{.fault = f}) {}
};
class Smd23eCorrect : public Smd23eVariant {
protected:
  Smd23eCorrect() : Smd23eVariant(Fault::None) {}
};
class Smd23eWrongAcceleration : public Smd23eVariant {
protected:
  Smd23eWrongAcceleration() : Smd23eVariant(*fault_from_name("wrong-acceleration")) {}
};
class Smd23eLostSteps : public Smd23eVariant {
protected:
  Smd23eLostSteps() : Smd23eVariant(*fault_from_name("lost-steps")) {}
};
class Smd23eIgnoredLimit : public Smd23eVariant {
protected:
  Smd23eIgnoredLimit() : Smd23eVariant(*fault_from_name("ignored-limit")) {}
};
class Smd23eLateStop : public Smd23eVariant {
protected:
  Smd23eLateStop() : Smd23eVariant(*fault_from_name("late-stop")) {}
};

TEST_F(Smd23eCorrect, ReferenceScenarios) {
  configure(ConfigWords{.control = 0b001});
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(1'000'001_us); // 1.0 s move
  EXPECT_TRUE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(dut.shaft_steps(sched.now()), 1000);
  command(msw::kJogCw);
  at(sched.now() + 500_ms, in1, Level::High);
  run_to(sched.now() + 500_ms);
  EXPECT_TRUE(bit1(sw1::kStopped)); // stopped the instant the limit went active
}

TEST_F(Smd23eWrongAcceleration, MoveTakesLongerThanTheFormula) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(1'000'001_us);
  // At half the acceleration the ramps take 0.2 s and 120 steps each: T = 0.4 + 760/1100.
  EXPECT_FALSE(bit1(sw1::kMoveComplete));
  EXPECT_EQ(dut.step_position(100_ms), 10 + 25); // 100·0.1 + ½·5000·0.01 instead of 60
}

TEST_F(Smd23eLostSteps, ShaftFallsBehindTheMotorPosition) {
  configure();
  command(msw::kRelative, kDrive, MoveWords{.value = 1000});
  run_to(2_s);
  EXPECT_EQ(position_word(), 1000);                   // the indexer counts what it issued
  EXPECT_EQ(dut.shaft_steps(sched.now()), 1000 - 10); // one step in every 100 lost
}

TEST_F(Smd23eIgnoredLimit, LimitDoesNotStopTheMove) {
  configure(ConfigWords{.control = 0b001});
  command(msw::kJogCw);
  at(500_ms, in1, Level::High);
  run_to(600_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCw));
  EXPECT_FALSE(bit1(sw1::kInputError));
}

TEST_F(Smd23eLateStop, StopActsLate) {
  configure(ConfigWords{.control = 0b001});
  command(msw::kJogCw);
  at(500_ms, in1, Level::High);
  run_to(500_ms);
  EXPECT_TRUE(bit1(sw1::kMovingCw)); // the correct model has stopped here
  run_to(520_ms);
  EXPECT_TRUE(bit1(sw1::kStopped));
  EXPECT_EQ(position_word(), 500 + 22); // 20 ms more at 1100 steps/s
}

} // namespace
} // namespace hilrig::models::smd23e::test
