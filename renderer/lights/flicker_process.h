#pragma once
// The random process a flame's flicker follows in a frame sequence (`ochre render --frames`,
// docs/lights.md#flicker): an Ornstein-Uhlenbeck process X(t) of mean 0, variance 1 and correlation time
// tau = 1 / (2 pi f_c) (autocorrelation exp(-|dt| / tau): a Lorentzian power spectrum with corner frequency
// f_c, the low-pass noise of a flame puffing near f_c), sampled exactly at the frame times t_k = k / fps:
//
//   X_0 = N_0,   X_k = a X_{k-1} + sqrt(1 - a^2) N_k,   a = exp(-(1 / fps) / tau),
//
// with N_k standard normal numbers that are pure functions of (seed, stream, k). X_k is therefore a pure
// function of (seed, stream, k, fps, f_c): frame k rendered alone equals frame k of a sequence, bit for bit
// (computing it costs k steps, microseconds for any real sequence).
//
// The intensity factor exp(s X - s^2 / 2), s^2 = ln(1 + r^2), is log-normal with mean exactly 1 and
// relative standard deviation r, and never negative.

#include <cstdint>

namespace ochre {

// Standard normal number, a pure function of its arguments (Box-Muller on two hashed uniforms).
double hashed_standard_normal(uint64_t seed, uint64_t stream, uint64_t index);

// The process above, frame by frame (frame 0 is t = 0).
class OuProcess {
 public:
  OuProcess(uint64_t seed, uint64_t stream, double fps, double corner_hz);
  double value() const { return x_; }
  uint64_t frame() const { return frame_; }
  void advance();  // to the next frame

 private:
  uint64_t seed_, stream_, frame_ = 0;
  double a_, b_, x_;
};

// X_frame of the process above: OuProcess advanced `frame` times.
double ou_process_value(uint64_t seed, uint64_t stream, uint64_t frame, double fps, double corner_hz);

// Mean-1 log-normal factor of relative standard deviation `relative_std` for a unit normal value x.
double lognormal_factor(double x, double relative_std);

}  // namespace ochre
