#pragma once
// A structure-aware libFuzzer mutator for the JSON targets (scene, material): byte mutations rarely turn
// valid JSON into other valid JSON, so most of them are rejected by the parser and the loaders behind it
// are reached seldom. This mutator parses the input and changes one value: another type (number, string,
// bool, null, array, object), an extreme number, a removed or added key (the scene format's and the
// nodes' names), a removed or repeated array element, or a copy of another part of the document. One
// mutation in four, and every input that is not JSON, goes to libFuzzer's own byte mutations instead.

#include <cstddef>
#include <cstdint>

namespace ochre::fuzz {

size_t mutate_json(uint8_t* data, size_t size, size_t max_size, unsigned seed);

}  // namespace ochre::fuzz

// Each JSON target's LLVMFuzzerCustomMutator.
#define OCHRE_FUZZ_JSON_MUTATOR                                                                           \
  extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned seed) { \
    return ochre::fuzz::mutate_json(data, size, max_size, seed);                                          \
  }
