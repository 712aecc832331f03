// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Is a render's error white or blue? The power spectrum of its luminance error (render − reference), radially
// averaged, summarised as the ratio of the mean power at high frequencies (0.25–0.5 cycles per pixel) to the
// mean power at low frequencies (above 0, up to 0.125 cycles per pixel): 1 for white noise, above 1 for
// blue noise (error pushed to fine scales, which the eye forgives), below 1 for blotchy, low-frequency error.
// The reference's own noise is white and pulls every ratio towards 1.
#pragma once

#include <vector>

#include "metrics/image_metrics.h"

namespace stipple::validation {

struct ErrorSpectrum {
    std::vector<double> radialPower; // mean |DFT|² per bin of width 1/64 cycles per pixel, from 0
    double highOverLow = 0;          // NaN when the image is too small (< 8 px on a side) or the error is zero
};

ErrorSpectrum errorSpectrum(const Image& reference, const Image& test);

} // namespace stipple::validation
