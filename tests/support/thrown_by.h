#pragma once
// The error a call throws, for tests of bad input: the test fails if the call returns instead.

#include <catch2/catch.hpp>

#include <string>

namespace mtcs_test {

template <class Error, class Call>
Error thrown_by(Call&& call, const std::string& input) {
  try {
    call();
  } catch (const Error& e) {
    return e;
  }
  FAIL("no error for:\n" << input);
  throw;
}

}  // namespace mtcs_test
