#pragma once
// Program: a compiled material as flat instruction lists over a frame of float registers (in the
// spirit of Cycles' SVM): no tree walk and no allocation per evaluation.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "materials/nodes/node_args.h"
#include "spectra/spectrum.h"

namespace ochre {

// Largest frame a material may use (floats; the frame lives on the stack during evaluation).
inline constexpr int kMaxFrameFloats = 4096;

// Instruction::gate of an instruction that always runs.
inline constexpr uint16_t kUngated = 0xffff;

struct Instruction {
  NodeFn fn = nullptr;
  const void* payload = nullptr;
  uint32_t first_operand = 0;  // into Program::operands: the inputs, then the outputs
  uint16_t input_count = 0;
  uint16_t output_count = 0;
  uint32_t outputs_used = 0;
  // A value instruction whose every result is multiplied by one float (program_builder.cpp, find_gates) is
  // skipped while that float's register holds 0: its outputs keep their initial 0 and the products are 0, as
  // they would have been (every value is finite, node_args.h). kUngated: always run.
  uint16_t gate = kUngated;
};

struct Program {
  std::vector<float> initial_frame;  // constants, zero closure weights, 1 for the output closure
  std::vector<uint16_t> operands;
  std::vector<Instruction> values;    // run first, in order
  std::vector<Instruction> closures;  // run next, in order (from the output towards the leaves)
  std::vector<std::string> value_labels, closure_labels;  // for listings
  std::vector<std::shared_ptr<const void>> payloads;      // keeps node data alive
  std::vector<SpectrumPtr> spectra;                       // keeps sampled constant spectra alive
};

}  // namespace ochre
