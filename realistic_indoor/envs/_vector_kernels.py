"""Compiled bookkeeping of the native vector environment: a step's accounts and observations.

After the batch's compiled step, a vector step counts steps, path and collisions, sums the
reward, measures coverage and builds the observation. In NumPy that is some sixty calls on
arrays of ``num_envs`` values, 100-170 us per step, much of it waiting on caches the step
evicted; these two kernels do it in two calls. Each value is computed by the same operations,
in the same order and precision, as the NumPy expressions they replace, so the results are the
same to the bit (``tests/envs/test_vector.py`` compares every step with the single
environment's).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from realistic_indoor.sim.disc_physics import THETA, V, W, X, Y, odometry
from realistic_indoor.sim.mapping import coverage_share_compiled


@njit(cache=True, nogil=True)
def account(
    stepped, terms, weights, motion, observed, reachable, cell_m2, max_steps, steps, path, collisions
):  # pragma: no cover - compiled
    """Count a step's progress in place and return its rewards, limits and coverage.

    Args:
        stepped: ``(n,)`` bool, the sub-environments that took a control step.
        terms: ``(n, T)`` float64 reward terms of the step.
        weights: ``(T,)`` float64 weight of each term, in the order the reward sums them.
        motion: ``(n,)`` distance driven in the step (m).
        observed: ``(n,)`` int64 reachable cells observed so far.
        reachable: ``(n,)`` reachable cells of each building (float64; 0 for none).
        cell_m2: ``(n,)`` area of a cell (m2).
        max_steps: Control steps after which an episode is truncated.
        steps: ``(n,)`` int64 control steps of each episode, counted here.
        path: ``(n,)`` path length (m), counted here.
        collisions: ``(n,)`` int64 steps that touched a wall, counted here.

    Returns:
        ``(reward, truncated, coverage, observed_m2, path, collisions, terms)``: new arrays;
        ``terms`` is ``(T, n)``, one row per term, and reward is 0 where no step was taken.
    """
    n, t = terms.shape
    reward = np.zeros(n)
    truncated = np.zeros(n, dtype=np.bool_)
    coverage = np.empty(n)
    observed_m2 = np.empty(n)
    by_term = np.empty((t, n))
    for i in range(n):
        went = stepped[i]
        steps[i] += 1 if went else 0
        path[i] = path[i] + motion[i] * (1.0 if went else 0.0)
        collisions[i] += 1 if (terms[i, 1] > 0 and went) else 0
        total = 0.0
        for j in range(t):
            total = total + weights[j] * terms[i, j]
            by_term[j, i] = terms[i, j]
        if went:
            reward[i] = total
            truncated[i] = steps[i] >= max_steps
        coverage[i] = coverage_share_compiled(observed[i], reachable[i])
        observed_m2[i] = observed[i] * cell_m2[i]
    return reward, truncated, coverage, observed_m2, path.copy(), collisions.copy(), by_term


@njit(cache=True, nogil=True)
def observe(
    phys,
    start_x,
    start_y,
    start_heading,
    start_cos,
    start_sin,
    vw_limits,
    pose_limit,
    scan_m,
    scan_scale,
    local,
):  # pragma: no cover - compiled
    """The batched observation's arrays (new ones) from the robots' states.

    Args:
        phys: ``(n, STATE_SIZE)`` physics state (:mod:`~realistic_indoor.sim.disc_physics`).
        start_x: ``(n,)`` start position x of each episode (m).
        start_y: ``(n,)`` start position y (m).
        start_heading: ``(n,)`` start heading (rad).
        start_cos: ``(n,)`` its cosine.
        start_sin: ``(n,)`` its sine.
        vw_limits: ``(2,)`` speed and turn rate limits (m/s, rad/s).
        pose_limit: Bound of the odometry position (m).
        scan_m: ``(n, B)`` float32 readings (m).
        scan_scale: float32 ``1 / max range`` (1/m).
        local: ``(n, 1, S, S)`` uint8 local views.

    Returns:
        ``(scan, local, velocity, pose)``: float32 ``(n, B)`` readings over the range, at most
        1; a copy of the local views; float32 ``(n, 2)`` velocities within the limits; float32
        ``(n, 3)`` odometry ``(x, y, heading)`` in the start's frame, positions clipped to
        ``pose_limit``, heading in ``[-pi, pi)``.
    """
    n, b = scan_m.shape
    scan = np.empty((n, b), dtype=np.float32)
    one = np.float32(1.0)
    for i in range(n):
        for j in range(b):
            scan[i, j] = np.minimum(scan_m[i, j] * scan_scale, one)
    velocity = np.empty((n, 2), dtype=np.float32)
    pose = np.empty((n, 3), dtype=np.float32)
    for i in range(n):
        velocity[i, 0] = np.minimum(np.maximum(phys[i, V], -vw_limits[0]), vw_limits[0])
        velocity[i, 1] = np.minimum(np.maximum(phys[i, W], -vw_limits[1]), vw_limits[1])
        x, y, heading = odometry(
            phys[i, X],
            phys[i, Y],
            phys[i, THETA],
            start_x[i],
            start_y[i],
            start_heading[i],
            start_cos[i],
            start_sin[i],
        )
        pose[i, 0] = np.minimum(np.maximum(x, -pose_limit), pose_limit)
        pose[i, 1] = np.minimum(np.maximum(y, -pose_limit), pose_limit)
        pose[i, 2] = heading
    return scan, local.copy(), velocity, pose
