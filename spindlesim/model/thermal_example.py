"""Example layout: the thermal side of the embedded milling spindle deck (spindlesim/decks/milling_spindle.yaml).

Shaft sections, bearing sets and the motor rotor follow that deck (HSK-A63, 24,000 rpm, 7014C-size
hybrid DB pair at z = 52.5 mm, 7012C-size steel DB pair at z = 390 mm, rotor OD 110 / ID 75 mm over
z = 120-300 mm).  What the deck does not say is our estimate, for tests and benchmarks, not a
product: housing 20-430 mm with walls of 25-30 mm; stator OD 160 mm, gap 0.5 mm; motor 18 kW at
9000 rpm base speed, efficiency 0.90; a helical water jacket around the stator (one channel of
8 mm hydraulic diameter, 10 turns: 5.3 m developed length, 4 L/min at 20 degC); silicon nitride
balls k = 25 W/(m K), c_p = 700 J/(kg K) (Si3N4: 20-30 W/(m K)); nominal ball loads from the
preloads (front ~150 N, rear 300 N / (17 sin 15 deg) = 68 N).
"""

from __future__ import annotations

import math

from ..bearings.ball.thermal import SILICON_NITRIDE
from ..bearings.conductance import ball_set
from ..thermal.layout import CoolingJacket, HousingSegment, MotorLayout, ShaftSegment, SpindleLayout
from ..thermal.motor import MotorRating

#: (OD, length) of the deck's 18 shaft elements [mm]; bore 36 mm
_SHAFT_MM = [(90, 15), (90, 15), (70, 22.5), (70, 22.5), (80, 22.5), (80, 22.5)] + [(75, 30)] * 6 + \
            [(65, 35), (65, 35), (60, 20), (60, 20), (50, 15), (50, 15)]
#: housing (ID, OD, length) [mm] from z = 20 mm
_HOUSING_MM = [(110, 170, 30), (110, 170, 30), (100, 170, 40)] + [(160, 210, 30)] * 6 + \
              [(95, 170, 35), (95, 170, 35), (95, 150, 20), (95, 150, 20), (60, 150, 20)]


def milling_spindle_layout(*, ambient_C: float = 20.0, coolant_l_min: float = 4.0, inlet_C: float = 20.0,
                           jacket_segments: int = 6) -> SpindleLayout:
    """The example spindle (module docstring), SI."""
    mm = 1e-3
    shaft = tuple(ShaftSegment(l * mm, d * mm, 36 * mm, "ambient" if k in (0, 1, 17) else "housing")
                  for k, (d, l) in enumerate(_SHAFT_MM))
    housing = tuple(HousingSegment(l * mm, di * mm, do * mm) for di, do, l in _HOUSING_MM)
    a15 = math.radians(15.0)
    front = ball_set("front", 52.5 * mm, 70 * mm, 110 * mm, 40 * mm, 36, 12.7 * mm, 90 * mm, a15, 150.0,
                     ball=SILICON_NITRIDE, ball_E_Pa=310e9, ball_poisson=0.26)
    rear = ball_set("rear", 390 * mm, 60 * mm, 95 * mm, 36 * mm, 34, 11.1125 * mm, 77.5 * mm, a15,
                    300.0 / (17 * math.sin(a15)))
    motor = MotorLayout(120 * mm, 180 * mm, 75 * mm, 110 * mm, 160 * mm, 0.5 * mm,
                        MotorRating(18e3, 0.90, 9000 * math.pi / 30))
    jacket = CoolingJacket(120 * mm, 180 * mm, 1, 8 * mm, 10 * math.pi * 0.17, coolant_l_min / 60e3, inlet_C,
                           segments=jacket_segments)
    return SpindleLayout(shaft, housing, (front, rear), ambient_C, 20 * mm, jacket, motor)
