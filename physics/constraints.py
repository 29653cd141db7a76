"""Positions set after a step rather than forces: held items, hard anchors, item-to-item anchors.

Shared by both modes.  An item anchored to another (a follower) is rigidly attached: its forces
are handed to the root of its chain and its centre is set from the root's after every step.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies


def hand_forces_to_roots(forces: np.ndarray, roots: np.ndarray, followers: np.ndarray) -> None:
    """Add every follower's force to its root's, in place, and zero the follower's own."""
    if followers.any():
        np.add.at(forces, roots[followers], forces[followers])
        forces[followers] = 0.0


def enforce_positions(bodies: Bodies, roots: np.ndarray, root_offsets: np.ndarray) -> None:
    """In place: held items stop, hard anchors snap to their point, followers to their root.

    Hard anchors come first so that a follower of a hard-anchored item lands beside it.
    """
    bodies.velocities[bodies.held | bodies.decorative] = 0.0
    hard = bodies.hard & ~bodies.held
    if hard.any():
        bodies.centres[hard] = bodies.anchors[hard]
        bodies.velocities[hard] = 0.0
    followers = bodies.followers & ~bodies.held
    if followers.any():
        bodies.centres[followers] = bodies.centres[roots[followers]] + root_offsets[followers]
        bodies.velocities[followers] = bodies.velocities[roots[followers]]
