"""Cylindrical roller bearing of seed 000 (issue 4), under any rotor (``type: roller``).

- ``section``: deck keys of ``type: roller`` (:class:`RollerEntry`, the models of its parts) and :func:`build`.
- ``bearing``: the bearing contract, :class:`RigidRaceBearing` and :class:`FlexibleRaceBearing`.
- ``rigid_race``: the classical 2-DOF model with rigid races (Sunnersjo 1978; Harsha and Kankar 2004).
- ``flexible_race``: seed 000's model, the outer race as rigid segments joined by co-rotational beams
  (``outer_race``, eqs. 5-17), the roller to race contact search (``contact_search``, eqs. 18-29) and
  compliant contacts with friction (``contact_force``, eqs. 30-31).
- ``kinematics``: cage and roller kinematics with slip (seed 000 eqs. 1-4); ``load_distribution``: the
  quasi-static (Stribeck) load distribution.
- ``rigid_race_kernel``, ``flexible_race_kernel``: the same forces compiled with numba.

The rig section ``transient:`` and the integrator settings belong to the transient analysis
(``spindlesim.deck.transient``).
"""
