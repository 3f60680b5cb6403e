// Who holds the treat: human 1 wears the red shirt, human 2 the yellow one (specs/go1_treat.oasis).
#pragma once

#include <cassert>
#include <cstddef>

namespace oasis::hw {

enum class TreatHolder { kNone = 0, kHuman1 = 1, kHuman2 = 2 };

// Person 0 is human 1 and person 1 human 2: the index of PerceptionResult::humans.
inline TreatHolder holder_of_person(std::size_t person) {
  assert(person < 2);
  return person == 0 ? TreatHolder::kHuman1 : TreatHolder::kHuman2;
}

// The index of the person holding the treat; `holder` must not be kNone.
inline std::size_t person_of_holder(TreatHolder holder) {
  assert(holder != TreatHolder::kNone);
  return static_cast<std::size_t>(holder) - 1;
}

}  // namespace oasis::hw
