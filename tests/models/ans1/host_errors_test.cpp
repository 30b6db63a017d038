// Programming errors (spec §5.6, L2304-L2309): every code is reachable through command words,
// a rejected block keeps the old setup, and the codes clear as the manual says.
#include <gtest/gtest.h>

#include "host_rig.hpp"

namespace hilrig::models::ans1 {
namespace {

using test::block;
using test::HostRig;

struct Case {
  const char* what;
  HostWords words;
  ErrorCode expected;
};

void expect_all(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    HostRig rig; // fresh device: each case alone
    EXPECT_EQ(rig.send(c.words), c.expected) << c.what;
  }
}

TEST(HostErrors, UndefinedBlockNumbersAreCommandWordErrors) {
  // Blocks 12..14 are undefined (§5.2) [MODEL A43: 1000].
  expect_all({{"CB12", block(12, {}), ErrorCode::CommandWord},
              {"CB13", block(13, {}), ErrorCode::CommandWord},
              {"CB14", block(14, {}), ErrorCode::CommandWord}});
}

TEST(HostErrors, OutOfRangeValuesAreParameterErrors) {
  expect_all({
      {"CB1 attribute 9", block(1, {8}, {{1, 9}, {2, 1}, {3, 1}}), ErrorCode::Parameter},
      {"CB1 attribute 21", block(1, {8}, {{1, 21}}), ErrorCode::Parameter},
      {"CB1 DA1 output 0", block(1, {8}, {{1, 1}, {2, 0}}), ErrorCode::Parameter},
      {"CB1 DA18 input 17", block(1, {8}, {{1, 18}, {3, 17}}), ErrorCode::Parameter},
      {"CB2 CPC 1", block(2, {8}, {{2, 1}}), ErrorCode::Parameter},
      {"CB2 CPC 4097", block(2, {8}, {{2, 4097}}), ErrorCode::Parameter},
      {"CB2 FSC 0", block(2, {9}, {{3, 0}}), ErrorCode::Parameter},
      {"CB2 FSC > CPC", block(2, {8, 9}, {{2, 1000}, {3, 1001}}), ErrorCode::Parameter},
      {"CB2 SMO 360", block(2, {10}, {{4, 360}}), ErrorCode::Parameter},
      {"CB2 SMO -360", block(2, {10}, {{4, -360}}), ErrorCode::Parameter},
      {"CB2 MPV 360", block(2, {11}, {{5, 360}}), ErrorCode::Parameter},
      {"CB2 MPI 17", block(2, {11}, {{6, 17}}), ErrorCode::Parameter},
      {"CB3 output 17", block(3, {10}, {{1, 17}}), ErrorCode::Parameter},
      {"CB3 To 360", block(3, {10}, {{1, 1}, {4, 10}, {5, 360}}), ErrorCode::Parameter},
      {"CB3 offset 360", block(3, {8}, {{1, 1}, {2, 360}}), ErrorCode::Parameter},
      {"CB3 preset input 17", block(3, {9}, {{1, 1}, {2, 17}}), ErrorCode::Parameter},
      {"CB4 output 0", block(4, {6}, {{1, 0}}), ErrorCode::Parameter},
      {"CB5 lead 32768", block(5, {8}, {{1, 1}, {2, 32768}}), ErrorCode::Parameter},
      {"CB5 VAT 10000", block(5, {9}, {{1, 1}, {3, 10000}}), ErrorCode::Parameter},
      {"CB5 timer 32768", block(5, {10}, {{1, 1}, {4, 32768}}), ErrorCode::Parameter},
      {"CB6 ANDing mode 4", block(6, {8}, {{1, 1}, {2, 4}}), ErrorCode::Parameter},
      {"CB6 window 360", block(6, {8}, {{1, 1}, {18, 360}}), ErrorCode::Parameter},
      {"CB6 RPM -32768", block(6, {9}, {{1, 1}, {2, -32768}}), ErrorCode::Parameter},
      {"CB6 SR bit 257", block(6, {10}, {{1, 1}, {4, 257}}), ErrorCode::Parameter},
      {"CB7 input 0", block(7, {9}, {{2, 0}}), ErrorCode::Parameter},
      {"CB7 mode 6", block(7, {9}, {{2, 1}, {3, 6}}), ErrorCode::Parameter},
      {"CB7 window 360", block(7, {9}, {{2, 1}, {3, 3}, {4, 360}}), ErrorCode::Parameter},
      {"CB7 action 4", block(7, {10}, {{2, 1}, {12, 4}}), ErrorCode::Parameter},
      {"CB7 fault output 17", block(7, {8}, {{1, 17}, {2, 1}}), ErrorCode::Parameter},
      {"CB8 input 17", block(8, {8}, {{1, 17}}), ErrorCode::Parameter},
      {"CB8 CSC 256", block(8, {9}, {{2, 256}}), ErrorCode::Parameter},
      {"CB8 start limit 32768", block(8, {10}, {{3, 32768}}), ErrorCode::Parameter},
      {"CB8 stop output 17", block(8, {13}, {{6, 17}}), ErrorCode::Parameter},
      {"CB9 input 17", block(9, {8}, {{1, 17}}), ErrorCode::Parameter},
      {"CB9 shift position 360", block(9, {8}, {{1, 1}, {4, 360}}), ErrorCode::Parameter},
      {"CB10 increment 360", block(10, {8}, {{1, 360}}), ErrorCode::Parameter},
      {"CB10 multiplier 0", block(10, {9}, {{2, 0}, {3, 1}}), ErrorCode::Parameter},
      {"CB10 divisor 32768", block(10, {9}, {{2, 1}, {3, 32768}}), ErrorCode::Parameter},
      {"CB11 counter 6", block(11, {}, {{1, 6}}), ErrorCode::Parameter},
      {"CB11 output mode 3", block(11, {9}, {{1, 1}, {3, 3}}), ErrorCode::Parameter},
      // W-15: 999,999,999 = 0x3B9AC9FF is the largest; one more is out of range.
      {"CB11 limit 1e9", block(11, {11}, {{1, 1}, {5, 0x3B9A}, {6, 0xCA00}}), ErrorCode::Parameter},
      {"CB11 preset 1e9", block(11, {12}, {{1, 1}, {7, 0x3B9A}, {8, 0xCA00}}), ErrorCode::Parameter},
      {"CB15 slot 41", block(15, {8}, {{1, 41}}), ErrorCode::Parameter},
      {"CB15 load empty slot", block(15, {8}, {{1, 5}}), ErrorCode::Parameter},
  });
}

// Tables 5.1 and 6.1 (L1766, L2279): DA19 takes "Additional data for Output defined in word 2
// Additional data for Input defined in word 3", so word 3 must name an input 1..16 as for
// DA4, DA16 and DA18 (L1758, L1763, L1765): 0 and 17 are Parameter Errors, 1 and 16 are not.
TEST(HostErrors, DataAttributeNineteenNeedsAnInputInWordThree) {
  expect_all({
      {"CB1 DA19 input 0", block(1, {8}, {{1, 19}, {2, 1}, {3, 0}}), ErrorCode::Parameter},
      {"CB1 DA19 input 17", block(1, {8}, {{1, 19}, {2, 1}, {3, 17}}), ErrorCode::Parameter},
      {"CB1 DA19 input 1", block(1, {8}, {{1, 19}, {2, 1}, {3, 1}}), ErrorCode::None},
      {"CB1 DA19 input 16", block(1, {8}, {{1, 19}, {2, 16}, {3, 16}}), ErrorCode::None},
      {"CB1 DA19 output 0", block(1, {8}, {{1, 19}, {2, 0}, {3, 1}}), ErrorCode::Parameter},
      {"CB1 DA19 output 17", block(1, {8}, {{1, 19}, {2, 17}, {3, 1}}), ErrorCode::Parameter},
      // The same words for DA4, DA16, DA18, which already check word 3.
      {"CB1 DA4 input 0", block(1, {8}, {{1, 4}, {2, 1}, {3, 0}}), ErrorCode::Parameter},
      {"CB1 DA16 input 17", block(1, {8}, {{1, 16}, {2, 1}, {3, 17}}), ErrorCode::Parameter},
      {"CB1 DA18 input 0", block(1, {8}, {{1, 18}, {2, 1}, {3, 0}}), ErrorCode::Parameter},
      // Blocks without an input word still ignore word 3 (L2267, L2277, L2280).
      {"CB1 DA0 input 0", block(1, {8}, {{1, 0}, {2, 1}, {3, 0}}), ErrorCode::None},
      {"CB1 DA17 input 0", block(1, {8}, {{1, 17}, {2, 1}, {3, 0}}), ErrorCode::None},
      {"CB1 DA20 input 0", block(1, {8}, {{1, 20}, {2, 1}, {3, 0}}), ErrorCode::None},
  });
}

TEST(HostErrors, ReservedBitsAreReservedBitsErrors) {
  expect_all({
      {"CB1 bit 7", block(1, {7}), ErrorCode::ReservedBits},
      {"CB1 bit 14", block(1, {14}), ErrorCode::ReservedBits},
      {"CB2 bit 6", block(2, {6}), ErrorCode::ReservedBits},
      {"CB2 w1 bit 5", block(2, {7}, {{1, 0x20}}), ErrorCode::ReservedBits},
      {"CB3 bit 7", block(3, {7}, {{1, 1}}), ErrorCode::ReservedBits},
      {"CB4 bit 5", block(4, {5}, {{1, 1}}), ErrorCode::ReservedBits},
      {"CB5 bit 12", block(5, {12}, {{1, 1}}), ErrorCode::ReservedBits},
      {"CB6 bit 11", block(6, {11}, {{1, 1}}), ErrorCode::ReservedBits},
      {"CB7 bit 7", block(7, {7}), ErrorCode::ReservedBits},
      {"CB8 bit 14", block(8, {14}), ErrorCode::ReservedBits},
      {"CB8 bit 6", block(8, {6}), ErrorCode::ReservedBits},
      {"CB9 bit 9", block(9, {9}), ErrorCode::ReservedBits},
      {"CB10 bit 10", block(10, {10}), ErrorCode::ReservedBits},
      {"CB11 bit 13", block(11, {13}), ErrorCode::ReservedBits},
      {"CB15 bit 11", block(15, {11}), ErrorCode::ReservedBits},
  });
}

TEST(HostErrors, IncompatibleParametersAreParameterConflicts) {
  expect_all({
      {"CB2 defaults with Apply", block(2, {5, 8}, {{2, 4096}}), ErrorCode::ParameterConflict},
      {"CB2 CPC below FSC", block(2, {8}, {{2, 100}}), ErrorCode::ParameterConflict},  // FSC stays 360
      {"CB3 bits 9:8 = 11", block(3, {9, 8}, {{1, 1}}), ErrorCode::ParameterConflict}, // L1869
      // L868: 10 counts cannot hold two Ons of 4 and an Off of 3 (needs 11).
      {"CB3 stitch too short", block(3, {10}, {{1, 1}, {4, 0}, {5, 10}, {6, 4}, {7, 3}}),
       ErrorCode::ParameterConflict},
      {"CB5 bits 9:8 = 11", block(5, {9, 8}, {{1, 1}}), ErrorCode::ParameterConflict}, // L1951
      {"CB6 bits 8+9", block(6, {8, 9}, {{1, 1}}), ErrorCode::ParameterConflict},      // L2028
      {"CB6 bits 8+10", block(6, {8, 10}, {{1, 1}}), ErrorCode::ParameterConflict},    // L2042
      {"CB6 two window inputs", block(6, {8}, {{1, 1}, {2, 3}, {3, 3}}), ErrorCode::ParameterConflict},
      {"CB11 counter 4 output", block(11, {8}, {{1, 4}, {2, 1}}), ErrorCode::ParameterConflict}, // L2187
      {"CB11 counter 5 limit", block(11, {11}, {{1, 5}, {6, 10}}), ErrorCode::ParameterConflict},
      {"CB11 counter 4 word 3", block(11, {}, {{1, 4}, {3, 1}}), ErrorCode::ParameterConflict},
      {"CB11 output without limit", block(11, {8, 9}, {{1, 1}, {2, 3}, {3, 1}}),
       ErrorCode::ParameterConflict},
      {"CB11 output in mode 0", block(11, {8, 11}, {{1, 1}, {2, 3}, {6, 5}}), ErrorCode::ParameterConflict},
      {"CB11 batch mode on counter 0", block(11, {10}, {{1, 0}, {4, 1}}), ErrorCode::ParameterConflict},
      {"CB15 bits 8+9", block(15, {8, 9}, {{1, 1}}), ErrorCode::ParameterConflict}, // L2237
      {"CB15 save to 40", block(15, {9}, {{1, 40}}), ErrorCode::ParameterConflict},
      {"CB15 save to active with none", block(15, {9}, {{1, 0}}), ErrorCode::ParameterConflict},
  });
}

// Every position a program block takes is 0..FSC-1 (L1800, L1890-L1891, L1867-L1868,
// L2005-L2006, L2056-L2063, L2139-L2141, L2158), as SMO and MPV are (L1801-L1802). The manual
// does not say what a smaller FSC does to them; [MODEL] (models/ans1/positions_fit.hpp): a CB2
// that would leave one outside its range is refused with 1011 and applies nothing. Each case
// programs its largest position 200 (an offset of -200): FSC 200 is refused, FSC 201 (the
// position at FSC - 1) is accepted (with Clear Errors, bit 4, for the 1011 before it).
TEST(HostErrors, AFullScaleCountAProgrammedPositionWouldNotFitIsAConflict) {
  const std::vector<std::pair<const char*, HostWords>> programs{
      {"CB2 SMO", block(2, {10}, {{4, 200}})},
      {"CB2 MPV", block(2, {11}, {{5, 200}})},
      {"CB3 From", block(3, {10}, {{1, 5}, {4, 200}, {5, 10}})},
      {"CB3 To", block(3, {10}, {{1, 5}, {4, 10}, {5, 200}})},
      {"CB3 To of pair 4", block(3, {13}, {{1, 5}, {16, 150}, {17, 200}})},
      {"CB3 LS offset", block(3, {8}, {{1, 5}, {2, -200}})},
      {"CB3 LS preset value", block(3, {9}, {{1, 5}, {2, 0}, {3, 200}})},
      {"CB6 window high", block(6, {8}, {{1, 5}, {18, 10}, {19, 200}})},
      {"CB7 trailing edge of window 4", block(7, {9}, {{2, 5}, {3, 2}, {10, 150}, {11, 200}})},
      {"CB9 sensing window To", block(9, {8}, {{1, 5}, {2, 10}, {3, 200}, {4, 20}})},
      {"CB9 shift position", block(9, {8}, {{1, 5}, {2, 10}, {3, 20}, {4, 200}})},
      {"CB10 increment position", block(10, {8}, {{1, 200}})},
  };
  for (const auto& [what, program] : programs) {
    HostRig rig;
    ASSERT_EQ(rig.send(program), ErrorCode::None) << what;
    EXPECT_EQ(rig.send(block(2, {9}, {{3, 200}})), ErrorCode::ParameterConflict) << what;
    EXPECT_EQ(rig.select(0)[7], 360) << what << ": nothing applied";
    EXPECT_EQ(rig.send(block(2, {4, 9}, {{3, 201}})), ErrorCode::None) << what;
    EXPECT_EQ(rig.select(0)[7], 201) << what;
  }
}

// A stitched pair must still hold two Ons and an Off (L868) in the new FSC. The pair 300 -> 100
// wraps: its length is 100 + FSC - 300, so On 40 + Off 60 (140 counts) fits down to FSC 340.
TEST(HostErrors, AFullScaleCountAStitchedPairWouldNotFitIsAConflict) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 5}, {4, 300}, {5, 100}, {6, 40}, {7, 60}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(2, {9}, {{3, 339}})), ErrorCode::ParameterConflict);
  EXPECT_EQ(rig.send(block(2, {4, 9}, {{3, 340}})), ErrorCode::None);
  // Once the pair is deleted (CB3 bit 6), nothing stops a smaller FSC.
  ASSERT_EQ(rig.send(block(3, {6}, {{1, 5}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(2, {9}, {{3, 10}})), ErrorCode::None);
}

// The same rule for a stored program (CB15 Load, L2237): it carries no FSC, so its positions
// must fit the one in force.
TEST(HostErrors, LoadingAProgramWhosePositionsExceedTheFullScaleCountIsAConflict) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 5}, {4, 10}, {5, 200}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(15, {9}, {{1, 3}})), ErrorCode::None); // save program 3
  ASSERT_EQ(rig.send(block(3, {6}, {{1, 5}})), ErrorCode::None);  // delete the pair in RAM
  ASSERT_EQ(rig.send(block(2, {9}, {{3, 200}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(15, {8}, {{1, 3}})), ErrorCode::ParameterConflict);
  EXPECT_EQ(rig.select(1, 5)[3], 0) << "nothing loaded";
  ASSERT_EQ(rig.send(block(2, {4, 9}, {{3, 201}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(15, {8}, {{1, 3}})), ErrorCode::None);
  EXPECT_EQ(rig.select(1, 5)[3], 200);
}

// CB11: only the Counter Overflow Output has requirements -- a limit programmed (L2208) and a
// mode other than "No Output" (L2212). The mode (L2213-L2214) and the limit (0..999,999,999,
// L2181) may each be programmed alone, in either order. A limit of 0 counts as none [MODEL]
// (a count never reaches it from below).
TEST(HostErrors, OnlyTheCounterOverflowOutputNeedsAModeAndALimit) {
  for (const int mode : {1, 2}) {
    HostRig rig;
    EXPECT_EQ(rig.send(block(11, {9}, {{1, 3}, {3, mode}})), ErrorCode::None) << "mode before limit";
    EXPECT_EQ(rig.send(block(11, {11}, {{1, 3}, {5, 0}, {6, 0}})), ErrorCode::None) << "limit 0 with a mode";
    EXPECT_EQ(rig.send(block(11, {8}, {{1, 3}, {2, 4}})), ErrorCode::ParameterConflict) << "output, limit 0";
    EXPECT_EQ(rig.send(block(11, {4, 11}, {{1, 3}, {5, 0}, {6, 1}})), ErrorCode::None) << "limit 1";
    EXPECT_EQ(rig.send(block(11, {8}, {{1, 3}, {2, 4}})), ErrorCode::None) << "output with mode and limit";
    EXPECT_EQ(rig.send(block(11, {11}, {{1, 3}, {5, 0}, {6, 0}})), ErrorCode::ParameterConflict)
        << "limit 0 under an output";
    EXPECT_EQ(rig.send(block(11, {4, 9}, {{1, 3}, {3, 0}})), ErrorCode::ParameterConflict)
        << "mode 0 under an output";
    const HostWords da8 = rig.select(8);
    EXPECT_EQ(da8[14], 4) << "batch 3 output kept";
    EXPECT_EQ(da8[15], mode) << "batch 3 mode kept";
    EXPECT_EQ(da8[18], 1) << "batch 3 limit kept";
    EXPECT_EQ(rig.send(block(11, {4, 8}, {{1, 3}, {2, 0}})), ErrorCode::None) << "output removed";
    EXPECT_EQ(rig.send(block(11, {11}, {{1, 3}, {5, 0}, {6, 0}})), ErrorCode::None) << "limit 0 again";
    EXPECT_EQ(rig.send(block(11, {9}, {{1, 3}, {3, 0}})), ErrorCode::None) << "mode 0 again";
  }
  HostRig rig; // limit first, then mode, then output; the largest limit (W-15)
  EXPECT_EQ(rig.send(block(11, {11}, {{1, 0}, {5, 0x3B9A}, {6, 0xC9FF}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(11, {9}, {{1, 0}, {3, 2}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(11, {8}, {{1, 0}, {2, 16}})), ErrorCode::None);
}

TEST(HostErrors, OverlappingPairsAreSetpointOverlapErrors) {
  // L1898: pairs [10, 20) and [15, 30) on one output share 15..19.
  HostRig rig;
  EXPECT_EQ(rig.send(block(3, {10, 11}, {{1, 4}, {4, 10}, {5, 20}, {8, 15}, {9, 30}})),
            ErrorCode::SetpointOverlap);
}

TEST(HostErrors, AdjustingFromOntoToWithSeveralPairsIsAnOverlap) {
  // L1907: moving From onto or past To of one of several pairs is an overlap. Pairs [10, 12)
  // and [100, 200): From-1 +1 gives [11, 12); +1 again gives From == To == 12, a pair that is
  // on everywhere (L1897) and so overlaps the other: 1100, and the pair stays [11, 12).
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10, 11}, {{1, 4}, {4, 10}, {5, 12}, {8, 100}, {9, 200}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(4, {14, 6}, {{1, 4}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(4, {14, 6}, {{1, 4}})), ErrorCode::SetpointOverlap);
  const HostWords da1 = rig.select(1, 4);
  EXPECT_EQ(da1[2], 11);
  EXPECT_EQ(da1[3], 12);
}

TEST(HostErrors, AdjustingToBelowFromWithSeveralPairsIsAnOverlap) {
  // To-2 of [100, 200) and [10, 12) moved down twice: [10, 11), then From == To == 10.
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10, 11}, {{1, 4}, {4, 10}, {5, 12}, {8, 100}, {9, 200}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(4, {7}, {{1, 4}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(4, {7}, {{1, 4}})), ErrorCode::SetpointOverlap);
  EXPECT_EQ(rig.select(1, 4)[3], 11);
}

TEST(HostErrors, AdjustingAStitchedOutputIsAConflict) {
  // L1905: stitched outputs cannot be adjusted (code not stated) [MODEL 1011].
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 1}, {4, 0}, {5, 100}, {6, 10}, {7, 5}})), ErrorCode::None);
  EXPECT_EQ(rig.send(block(4, {14, 7}, {{1, 1}})), ErrorCode::ParameterConflict);
}

TEST(HostErrors, RejectedBlockKeepsTheOldSetup) {
  // §5.6 [MODEL]: the whole block is checked first; nothing of a rejected block is applied.
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 6}, {4, 40}, {5, 80}})), ErrorCode::None);
  // Pair 1 valid, pair 2 out of range: neither is applied.
  EXPECT_EQ(rig.send(block(3, {10, 11}, {{1, 6}, {4, 1}, {5, 2}, {8, 5}, {9, 400}})), ErrorCode::Parameter);
  HostWords da1 = rig.select(1, 6);
  EXPECT_EQ(da1[2], 40);
  EXPECT_EQ(da1[3], 80);
  EXPECT_EQ(da1[6], 0);
  // The brake setup likewise (CSC valid, stop output out of range).
  ASSERT_EQ(rig.send(block(8, {8, 9}, {{1, 3}, {2, 20}})), ErrorCode::Parameter); // error still shown
  rig.transact(block(0, {4}));
  EXPECT_EQ(rig.send(block(8, {9, 13}, {{2, 99}, {6, 17}})), ErrorCode::Parameter);
  const HostWords da5 = rig.select(5);
  EXPECT_EQ(da5[1], 3);
  EXPECT_EQ(da5[2], 20);
}

TEST(HostErrors, ProgrammingErrorsStayUntilClearErrors) {
  // L2306-L2309: 1001..1100 need Clear Errors; a valid block without bit 4 leaves the code.
  HostRig rig;
  ASSERT_EQ(rig.send(block(8, {9}, {{2, 256}})), ErrorCode::Parameter);
  EXPECT_EQ(rig.send(block(8, {9}, {{2, 10}})), ErrorCode::Parameter); // accepted, code kept
  EXPECT_EQ(rig.select(5)[2], 10);                                     // ... and applied
  EXPECT_EQ(rig.send(block(0, {4})), ErrorCode::None);                 // CB0 with Clear Errors
}

TEST(HostErrors, ClearErrorsBitWorksInAnyBlock) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(3, {9, 8}, {{1, 1}})), ErrorCode::ParameterConflict);
  EXPECT_EQ(rig.send(block(8, {4, 9}, {{2, 10}})), ErrorCode::None);
  // Clear Errors in a block that is itself rejected: the old code goes, the new one shows.
  ASSERT_EQ(rig.send(block(8, {9}, {{2, 256}})), ErrorCode::Parameter);
  EXPECT_EQ(rig.send(block(3, {4, 7}, {{1, 1}})), ErrorCode::ReservedBits);
}

TEST(HostErrors, CommandWordErrorClearsWithTheNextValidCommand) {
  // L2305: 1000 is cleared by the next valid command word, no Clear Errors needed.
  HostRig rig;
  ASSERT_EQ(rig.send(block(14, {})), ErrorCode::CommandWord);
  EXPECT_EQ(rig.send(block(10, {8}, {{1, 5}})), ErrorCode::None);
}

// A 1000 on top of a code that needs Clear Errors: the 1000 shows, and the next valid command
// word clears it (L2305) but not the 1001 under it (L2306), which shows again until Clear Errors.
TEST(HostErrors, ACommandWordErrorDoesNotClearAProgrammingError) {
  HostRig rig;
  ASSERT_EQ(rig.send(block(8, {9}, {{2, 256}})), ErrorCode::Parameter);
  EXPECT_EQ(rig.send(block(14, {})), ErrorCode::CommandWord);
  EXPECT_EQ(rig.send(block(10, {8}, {{1, 5}})), ErrorCode::Parameter);
  EXPECT_EQ(rig.send(block(10, {8}, {{1, 5}})), ErrorCode::Parameter);
  EXPECT_EQ(rig.send(block(0, {4})), ErrorCode::None);
  // Clear Errors clears both: a 1000 after it, then a valid command, leaves no code.
  EXPECT_EQ(rig.send(block(14, {})), ErrorCode::CommandWord);
  EXPECT_EQ(rig.send(block(10, {8}, {{1, 5}})), ErrorCode::None);
}

TEST(HostErrors, CommandBlockZeroIgnoresEverythingButClearErrors) {
  // L1713-L1721: bits 14..5 and words 1..19 of CB0 are ignored.
  HostRig rig;
  EXPECT_EQ(rig.send(block(0, {14, 7, 5}, {{1, 0xFFFF}})), ErrorCode::None);
}

} // namespace
} // namespace hilrig::models::ans1
