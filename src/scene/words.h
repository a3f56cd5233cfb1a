// Radiance's number syntax for words of a scene file or transform (isint/isflt/atoi/atof).
#pragma once

#include <string>
#include <string_view>

namespace radcl::scene::detail {

// [+-]digits, after optional leading white space. With `trailing_space`, white space may
// also follow (as Radiance's badarg() allows for option values).
bool is_int_word(std::string_view s, bool trailing_space = false);
// [+-](digits[.digits]|.digits)[(e|E)[+-]digits]: no inf, nan or hex.
bool is_real_word(std::string_view s, bool trailing_space = false);

// Values of words that passed the checks above (saturating instead of atoi's overflow).
long long int_value(std::string_view s);
double real_value(const std::string& s);

} // namespace radcl::scene::detail
