#pragma once
// How the verifier writes a catalog's double in a message: ten significant digits, enough to
// tell a carried value from the exact one it should be near.

#include <string>

namespace oasis::verify {

std::string number_text(double value);

}  // namespace oasis::verify
