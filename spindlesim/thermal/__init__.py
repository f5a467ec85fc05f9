"""Spindle thermal model (issue 22): lumped heat-transfer network and its parts.

Modules (imported on first use of a name listed below, so ``import spindlesim.thermal`` stays light):

- ``network``: nodes, conductances, coolant advection; steady solve (linear, Picard, Newton) and the
  energy balance.
- ``transient``: warm-up integration (BDF/Radau with the exact Jacobian, implicit Euler), step profiles.
- ``properties``: air, water and water-glycol properties vs temperature.
- ``conduction``: cylindrical shells, rods, contact (seat) conductance.
- ``convection``: rotating shaft, rotor-stator gap (Taylor-Couette), free convection of a horizontal
  cylinder, channel flow (Gnielinski, Dittus-Boelter), spheres, radiation.
- ``bearing_conductance``: ball bearing internal conductances (Hertz contact ellipses, EHL film,
  ball convection).
- ``motor``: built-in motor losses (electrical split, speed dependence, rotor windage).
- ``spindle_network``: layout dataclasses of a motor spindle and the builder of its network.

The bearing heat generation and the thermal growth/preload live in the ``friction*`` and
``growth*`` modules of this package.
"""

from __future__ import annotations

from ..lazy import lazy_exports

__getattr__, __dir__ = lazy_exports(__name__, {
    "Node": "network", "Conductance": "network", "Advection": "network", "Network": "network",
    "SteadyState": "network", "EnergyBalance": "network", "ThermalConvergenceError": "network",
    "StepProfile": "transient", "TransientResult": "transient", "solve_transient": "transient",
})
