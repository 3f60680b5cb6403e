// The YAML layout of a controller profile (controller_profile.hpp), written once for the
// reader, the writer and the checks, as schema.hpp is for the settings.
#pragma once

#include "settings/controller_profile.hpp"
#include "settings/go1_codecs.hpp"

namespace oasis::hw::settings::detail {

inline const EnumCodec<rt::FilterMode> kModeCodec{{{"paper", rt::FilterMode::kPaper},
                                                   {"joint", rt::FilterMode::kJoint},
                                                   {"noise_aware", rt::FilterMode::kNoiseAware}}};
inline const EnumCodec<rt::TieRule> kTieRuleCodec{
    {{"keep", rt::TieRule::kKeep}, {"random", rt::TieRule::kRandom}}};
inline const EnumCodec<ControllerKind> kControllerKindCodec{
    {{"attention", ControllerKind::kAttention}, {"oracle", ControllerKind::kOracle}}};
inline const EnumCodec<ProfileCatalog> kProfileCatalogCodec{
    {{"session", ProfileCatalog::kSession}, {"full_state", ProfileCatalog::kFullState}}};

template <class V, class P>
void describe_profile(V& v, P& p) {
  v.value("description", p.description, TextCodec{}, "one line for tables and --help");
  v.value("kind", p.kind, kControllerKindCodec,
          "attention (the filter below), or oracle (told the truth: sim only)");
  v.value("catalog", p.catalog, kProfileCatalogCodec,
          "session (loop.catalog), or full_state (no-attention: sim only)");
  v.section(
      "filter",
      "The attention filter (runtime/include/oasis/rt/attention_filter.hpp). The defaults are\n"
      "Algorithm 1 of the paper.",
      [&] {
        v.value("mode", p.filter.mode, kModeCodec,
                "paper; joint (discrete catalogs) or noise_aware (continuous)");
        v.value("tie_rule", p.filter.tie_rule, kTieRuleCodec,
                "ties: keep the current abstraction, or random");
        v.value("seed", p.filter.seed, SeedCodec{}, "seed of the random tie rule");
        v.value("tie_tolerance", p.filter.tie_tolerance, closed<double>(0.0, 1.0),
                "beliefs this close are tied");
        v.value("reward_tolerance", p.filter.reward_tolerance, non_negative<double>(),
                "|observed - expected reward| <= this: a match");
        v.value("detection_epsilon", p.filter.detection_epsilon,
                RealCodec<double>{0.0, 1.0, false, true}, "0: the paper's exact detection model");
        v.value("zero_likelihood_guard", p.filter.zero_likelihood_guard, BoolCodec{},
                "no hypothesis fits: keep prediction, or prior");
      });
  v.section(
      "evidence",
      "The camera's treat tag beyond the reward (hw/loop/attention_controller.hpp). The defaults\n"
      "are the paper's: the tag decides the reward and nothing else.",
      [&] {
        v.value("treat_sighting", p.evidence.treat_sighting,
                RealCodec<double>{0.0, 1.0, false, true},
                "0: off; p: a seen tag names its holder with p");
        v.value("tag_unseen_likelihood", p.evidence.tag_unseen_likelihood,
                RealCodec<double>{0.0, 1.0, true, false},
                "1: off; p: p(no tag seen | holder, tag would show)");
        v.value("unknown_reward_when_tag_cut", p.evidence.unknown_reward_when_tag_cut, BoolCodec{},
                "no tag, a tag in reach out of image: reward unknown");
      });
}

}  // namespace oasis::hw::settings::detail
