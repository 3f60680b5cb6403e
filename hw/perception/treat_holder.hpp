// Who holds the treat: human 1 wears the red shirt, human 2 the yellow one (specs/go1_treat.oasis).
#pragma once

namespace oasis::hw {

enum class TreatHolder { kNone = 0, kHuman1 = 1, kHuman2 = 2 };

}  // namespace oasis::hw
