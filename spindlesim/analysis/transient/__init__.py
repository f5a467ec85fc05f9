"""Transient analysis: the one engine (``engine.simulate``) for any rotor with any bearings.

- ``system``: the equations (rotor + bearings' internal DOFs, excitation, speed profile)
- ``newmark``, ``explicit`` (+ ``explicit_kernel``), ``ivp``: the methods, one module each
- ``fixed_step``: exact stepping plans and the RK4 stability step
- ``spectrum``: windowed amplitude spectrum, Poincare helpers
- ``result``: what methods and the engine return
"""
