// SPDX-License-Identifier: GPL-2.0-or-later
// A core header that includes a higher layer: check_layers.py must refuse it.
#include "dsp/fft.h"
