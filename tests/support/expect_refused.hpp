#pragma once
// A test's check that an input is refused as bad input: the call throws
// InvalidInputError whose message names every one of `words` (the
// problem and where it was found).
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include "wtc/base/error.hpp"

namespace wtc::testing {

template <class Call>
void expectRefused(Call&& call, std::initializer_list<std::string> words) {
  try {
    call();
    ADD_FAILURE() << "accepted: " << *words.begin();
  } catch (const InvalidInputError& e) {
    for (const std::string& w : words) EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
  }
}

}  // namespace wtc::testing
