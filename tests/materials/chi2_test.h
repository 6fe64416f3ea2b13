#pragma once
// Forwarding header: the chi-square test of a Lobe's sample() against its pdf() now lives in
// materials/lobes/sampling_check.h so that tools (ochre-brdf chi2) and tests share one implementation.
// Kept so tests written against ochre::test::chi2_test compile unchanged.

#include "materials/lobes/sampling_check.h"

namespace ochre::test {

using ochre::chi2_test;
using ochre::Chi2Result;
using ochre::regularized_gamma_q;
using ochre::sidak_significance;

}  // namespace ochre::test
