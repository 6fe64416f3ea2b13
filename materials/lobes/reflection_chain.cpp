#include "materials/lobes/reflection_chain.h"

#include <algorithm>
#include <cmath>

#include "materials/lobes/fresnel.h"

namespace ochre {

FacetAmplitudes facet_amplitudes(const FacetIndex& facet, double cos_i) {
  if (facet.mirror) return {-1.0, 1.0};
  const FresnelAmplitudes<double> a = fresnel_amplitudes(std::clamp(cos_i, 0.0, 1.0), facet.eta);
  return {a.r_s, a.r_p};
}

namespace {

// Any unit vector perpendicular to the unit vector n (for normal incidence, where every such vector is
// an s axis and the Fresnel response does not depend on the choice).
Vec3d any_perpendicular(const Vec3d& n) {
  const Vec3d helper = std::fabs(n.x) < 0.6 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
  return normalize(cross(n, helper));
}

Vec3d s_axis(const Vec3d& d_in, const Vec3d& n) {
  const Vec3d s = cross(-d_in, n);
  const double len2 = dot(s, s);
  return len2 > 1e-28 ? s * (1.0 / std::sqrt(len2)) : any_perpendicular(n);
}

}  // namespace

ChainStep ChainFrames::reflect(const Vec3d& d_in, const Vec3d& n) {
  ChainStep step;
  step.cos_i = std::clamp(-dot(d_in, n), 0.0, 1.0);
  const Vec3d s = s_axis(d_in, n);
  if (count_ == 0) {
    first_s_ = s;
  } else {
    // From the previous s axis to this one about the propagation direction d_in, positive towards
    // y = cross(d_in, s_prev) (stokes_frame_angle in mueller.h, in double precision).
    const Vec3d y_prev = cross(d_in, last_s_);
    step.frame_angle = std::atan2(dot(s, y_prev), dot(s, last_s_));
    step.literal_angle = std::acos(std::min(1.0, std::fabs(dot(s, last_s_))));
  }
  last_s_ = s;
  outgoing_ = ochre::reflect(d_in, n);
  ++count_;
  return step;
}

void ChainResponse::add(const ChainStep& step) {
  const FacetAmplitudes r = facet_amplitudes(facet_, step.cos_i);
  switch (model_) {
    case ChainModel::kRigorous:
      // Rotate the field into this plane of incidence's frame, then reflect (fields in (E_s, E_y)).
      jones_ = Jones::diagonal(r.r_s, r.r_p) * Jones::frame_rotation(step.frame_angle) * jones_;
      break;
    case ChainModel::kPaperLiteral: {
      // Eqs 23-28 on (E_p, E_s) with M(psi) of Eq 25 and psi from Eq 33 (never negative). Eq 23 holds
      // with the convention r_p = r_s at normal incidence, i.e. minus the Verdet r_p.
      const double c = std::cos(step.literal_angle), s = std::sin(step.literal_angle);
      jones_ = Jones::diagonal(-r.r_p, r.r_s) * Jones{c, s, -s, c} * jones_;
      break;
    }
    case ChainModel::kSeparateSP:
      product_s_ *= std::norm(r.r_s);
      product_p_ *= std::norm(r.r_p);
      break;
    case ChainModel::kUnpolarized:
      product_ *= 0.5 * (std::norm(r.r_s) + std::norm(r.r_p));
      break;
  }
}

double ChainResponse::reflectance() const {
  switch (model_) {
    case ChainModel::kRigorous:
    case ChainModel::kPaperLiteral:
      // Eq 31 with squared moduli of the complex entries (the printed a^2 + ... is a typo).
      return unpolarized_gain(jones_);
    case ChainModel::kSeparateSP:
      return 0.5 * (product_s_ + product_p_);  // Eq 20 prints the sum; energy requires the average
    case ChainModel::kUnpolarized:
      return product_;
  }
  return 0.0;
}

Mueller ChainResponse::mueller() const {
  if (model_ == ChainModel::kRigorous) return jones_to_mueller(jones_);
  if (model_ == ChainModel::kSeparateSP) {
    Mueller m;
    m(0, 0) = m(1, 1) = static_cast<float>(0.5 * (product_s_ + product_p_));
    m(0, 1) = m(1, 0) = static_cast<float>(0.5 * (product_s_ - product_p_));
    return m;
  }
  return depolarizer(static_cast<float>(reflectance()));
}

}  // namespace ochre
