"""Spindle thermal model (issue 22): lumped heat-transfer network and its parts.

Modules (imported on first use of a name listed below, so ``import spindlesim.thermal`` stays light):

- ``network``: nodes, conductances, coolant advection; steady solve (linear, Picard, Newton) and the
  energy balance.
- ``transient``: warm-up integration (BDF/Radau with the exact Jacobian, implicit Euler), step profiles.
- ``properties``: air, water and water-glycol properties vs temperature.
- ``conduction``: cylindrical shells, rods, contact (seat) conductance.
- ``convection``: rotating shaft, rotor-stator gap (Taylor-Couette), free convection of a horizontal
  cylinder, channel flow (Gnielinski, Dittus-Boelter), spheres, radiation.
- ``motor``: built-in motor losses (electrical split, speed dependence, rotor windage).
- ``layout``, ``spindle_network``: layout dataclasses of a motor spindle (a bearing set carries its family's
  contact paths, ``spindlesim/bearings/conductance.py``) and the builder of its network.
- ``section``: the deck section ``spindle_thermal:``.
- ``oil``: lubricant viscosity (Walther / ASTM D341, ISO VG grades).
- ``friction``: Palmgren's global friction moments and the lubricant (the ball family's local model is
  ``spindlesim/bearings/ball/heat.py``).
- ``growth``, ``growth_bearings``: thermal, fit and centrifugal growth of shaft, rings, rolling
  elements and housing (what it does to one family's clearance or preload is the family's:
  ``bearings/<family>/growth.py`` or ``thermal.py``).

The package sits below the bearings (it imports none of the rest of spindlesim): the bearing families
call its functions.  docs/theory.md, "Spindle thermal model".
"""

from __future__ import annotations

from ..lazy import lazy_exports

__getattr__, __dir__ = lazy_exports(__name__, {
    "Node": "network", "Conductance": "network", "Advection": "network", "Network": "network",
    "SteadyState": "network", "EnergyBalance": "network", "ThermalConvergenceError": "network",
    "StepProfile": "transient", "TransientResult": "transient", "solve_transient": "transient",
})
