// Attention by exact projection: the variables a context attends to are those its rewards
// read, closed under the dynamics, and nothing else.

#include "geom/relevance.hpp"

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/run_oasisc.hpp"
#include "../../support/spec_models.hpp"
#include "frontend/load_spec.hpp"

namespace oasis {
namespace {

std::vector<std::string> names(const model::ModelIR& ir,
                               const std::vector<std::uint32_t>& indices) {
  std::vector<std::string> out;
  for (const std::uint32_t v : indices)
    out.push_back(ir.continuous[v].name);
  return out;
}

using Names = std::vector<std::string>;

TEST(Relevance, Go1TreatAttendsToTheTreatHolderOnly) {
  const model::ModelIR ir_value = test::shipped_go1_spec();
  const model::ModelIR* ir = &ir_value;
  ASSERT_EQ(ir->contexts.size(), 2U);
  const geom::Relevance first = geom::analyse_relevance(*ir, 0);
  EXPECT_EQ(names(*ir, first.relevant), (Names{"x1", "y1"}));
  EXPECT_EQ(names(*ir, first.ignored), (Names{"x2", "y2"}));
  EXPECT_TRUE(first.exact());
  const geom::Relevance second = geom::analyse_relevance(*ir, 1);
  EXPECT_EQ(names(*ir, second.relevant), (Names{"x2", "y2"}));
  EXPECT_EQ(names(*ir, second.ignored), (Names{"x1", "y1"}));
}

// x is rewarded; under 'drift' x' reads y, and y' reads z: all three matter. w is only read
// by its own dynamics and never by a relevant variable's.
constexpr const char* kChain = R"(
mdp chain {
  continuous x : [0 .. 1];
  continuous y : [0 .. 1];
  continuous z : [0 .. 1];
  continuous w : [0 .. 1];
  actions drift, stay;
  disturbance x in [-0.1 .. 0.1];
  dynamics [drift] { x' = x + y / 2; y' = y - z / 4; w' = w + x / 8; }
  dynamics [stay] { }
  region high = x >= 1/2;
}
catalog {
  context rewarded_x { reward high : 1; }
  context rewarded_w { reward w <= 1/4 : 1; }
  switching stay 0.9;
}
)";

TEST(Relevance, ClosesOverTheDynamicsOfRelevantVariables) {
  const model::ModelIR ir = test::check_spec_text_ir(kChain);
  ASSERT_EQ(ir.contexts.size(), 2U);
  const geom::Relevance x = geom::analyse_relevance(ir, 0);
  EXPECT_EQ(names(ir, x.relevant), (Names{"x", "y", "z"}));
  EXPECT_EQ(names(ir, x.ignored), (Names{"w"}));
  ASSERT_EQ(x.reasons.size(), 3U);
  EXPECT_EQ(x.reasons[0], "a reward condition");
  EXPECT_EQ(x.reasons[1], "the dynamics of 'x' under 'drift'");
  EXPECT_EQ(x.reasons[2], "the dynamics of 'y' under 'drift'");
  EXPECT_TRUE(x.exact());
}

TEST(Relevance, ReadingARelevantVariableDoesNotMakeAVariableRelevant) {
  // w' reads x, but the reward on w makes w relevant and, through its dynamics, x, y and z.
  const model::ModelIR ir = test::check_spec_text_ir(kChain);
  const geom::Relevance w = geom::analyse_relevance(ir, 1);
  EXPECT_EQ(names(ir, w.relevant), (Names{"x", "y", "z", "w"}));
  EXPECT_TRUE(w.ignored.empty());
}

TEST(Relevance, FullStateKeepsEveryVariable) {
  const model::ModelIR ir = test::check_spec_text_ir(kChain);
  const geom::Relevance all = geom::full_state(ir);
  EXPECT_EQ(names(ir, all.relevant), (Names{"x", "y", "z", "w"}));
  EXPECT_TRUE(all.ignored.empty());
  EXPECT_TRUE(all.exact());
}

TEST(Relevance, AContextsOwnDynamicsDecide) {
  const model::ModelIR ir = test::check_spec_text_ir(R"(
mdp own {
  continuous x : [0 .. 1];
  continuous y : [0 .. 1];
  actions go;
  dynamics [go] { }
}
catalog {
  context coupled {
    dynamics [go] { x' = x + y / 2; }
    reward x >= 1/2 : 1;
  }
  context plain {
    reward x >= 1/2 : 1;
  }
  switching stay 0.5;
}
)");
  ASSERT_EQ(ir.contexts.size(), 2U);
  EXPECT_EQ(names(ir, geom::analyse_relevance(ir, 0).relevant), (Names{"x", "y"}));
  EXPECT_EQ(names(ir, geom::analyse_relevance(ir, 1).relevant), (Names{"x"}));
}

TEST(Relevance, InfoJsonReportsIt) {
  const auto result =
      test::run_oasisc("info --json " + std::string(OASIS_SOURCE_DIR) + "/specs/go1_treat.oasis");
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  ASSERT_EQ(json["contexts"].size(), 2U);
  EXPECT_EQ(json["contexts"][0]["name"], "human1_holds_treat");
  EXPECT_EQ(json["contexts"][0]["relevant_variables"], nlohmann::json({"x1", "y1"}));
  EXPECT_EQ(json["contexts"][0]["ignored_variables"], nlohmann::json({"x2", "y2"}));
  EXPECT_EQ(json["contexts"][0]["exact_projection"], true);
  EXPECT_EQ(json["contexts"][1]["name"], "human2_holds_treat");
  EXPECT_EQ(json["contexts"][1]["relevant_variables"], nlohmann::json({"x2", "y2"}));
  EXPECT_EQ(json["contexts"][1]["ignored_variables"], nlohmann::json({"x1", "y1"}));
}

}  // namespace
}  // namespace oasis
