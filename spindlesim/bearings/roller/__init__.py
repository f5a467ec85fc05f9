"""Rolling-element bearing models for transient analysis (issue 4).

- ``kinematics``: cage and roller kinematics with slip (seed 000 eqs. 1-4).
- ``hertz``: Hertz/Palmgren contact stiffness and the quasi-static
  (Stribeck) load distribution.
- ``rigid_race``: the classical 2-DOF rotor in a rolling bearing with rigid
  races (Sunnersjo 1978; Harsha and Kankar 2004).
- ``outer_race``: outer race as rigid segments joined by co-rotational beams
  (seed 000 eqs. 5-17).
- ``contact_search``: roller to outer race contact search (seed 000 eqs. 18-29).
- ``contact_force``: compliant contact force with friction (seed 000 eqs. 30-31).
- ``flexible_race``: the assembled seed 000 model.
- ``rigid_race_kernel``, ``flexible_race_kernel``, ``rk4_parts``: the same
  right-hand sides compiled with numba, and their fixed-step RK4 loops.
"""
