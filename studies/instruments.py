#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The instruments of the studies: the electrical channel (the deck's injected current, so that
the instrument reads V = I R) and the detectability study's 100 mV/g accelerometer, each as a
chain for `ohmdem-post acquire` (the sizing studies' 10 mV/g one: sizing.ACC_SENSITIVITY and
sizing.acquire_acc). Imported by detectability.py, sizing.py and the studies built on them; it
imports no study.
"""
import common

CURRENT = common.deck_defaults()["I"]  # A, the deck's injected current: the instrument reads V = I R
SENSITIVITY = 0.0102   # V per m/s^2: a 100 mV/g accelerometer

# Per channel: the column, the scale to volts, the ADC range (V) and three noise densities
# (V/sqrt(Hz)) named low/mid/high. Electrical: 10 nV/sqrt(Hz) is a low-noise preamplifier,
# 1 uV/sqrt(Hz) a plain data-acquisition input. Vibration: 5e-5, 5e-4, 5e-3 (m/s^2)/sqrt(Hz)
# (5 to 500 ug/sqrt(Hz): a good piezoelectric accelerometer to a MEMS one) times the
# sensitivity. ADC ranges: 0-0.1 V for I R (R ~ 0.5 ohm here), +-0.5 V (+-5 g) for the
# accelerometer.
CHANNELS = {
    "R": {"column": "R", "scale": CURRENT, "range": (0.0, 0.1),
          "noise": {"low": 1e-8, "mid": 1e-7, "high": 1e-6}, "unit": "V"},
    "acc": {"column": "acc_along", "scale": SENSITIVITY, "range": (-0.5, 0.5),
            "noise": {"low": 5e-5 * SENSITIVITY, "mid": 5e-4 * SENSITIVITY,
                      "high": 5e-3 * SENSITIVITY}, "unit": "V"},
}
