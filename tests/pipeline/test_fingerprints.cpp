// The taxonomy's fingerprint, on which the label maps (and every stage after them) are redone: every field
// of every class counts, the built-in taxonomy's included (it has no file whose bytes could be hashed).
#include <gtest/gtest.h>

#include <functional>

#include "pipeline/fingerprints.h"

using namespace cls;

TEST(Fingerprints, EveryFieldOfTheTaxonomyChangesItsFingerprint) {
  const Taxonomy builtin = Taxonomy::builtin();
  const std::string base = taxonomy_fingerprint(builtin);
  EXPECT_EQ(taxonomy_fingerprint(Taxonomy::builtin()), base);
  const std::vector<std::function<void(Taxonomy&)>> changes = {
      [](Taxonomy& t) { t.classes.pop_back(); },
      [](Taxonomy& t) { t.classes[0].name += "s"; },
      [](Taxonomy& t) { t.classes[0].level = 2; },
      [](Taxonomy& t) { t.classes[0].source_types.push_back("Opening"); },
      [](Taxonomy& t) { t.classes[0].prompts.push_back("pane"); },
      [](Taxonomy& t) { t.classes[0].color[1] ^= 1; },
      [](Taxonomy& t) { std::swap(t.classes[0], t.classes[1]); },
  };
  for (size_t i = 0; i < changes.size(); ++i) {
    Taxonomy t = builtin;
    changes[i](t);
    EXPECT_NE(taxonomy_fingerprint(t), base) << "change " << i;
  }
}
