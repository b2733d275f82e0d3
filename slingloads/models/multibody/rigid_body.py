"""The carried helicopter as a rigid body: mass properties and attitude kinematics.

Attitude is a unit quaternion ``q = (q0, q1, q2, q3)`` that rotates airframe (body) axes into
the earth axes of the simulation (X aft along the flight path, Y right, Z up; see
``docs/multibody.md``): a vector with body components ``b`` has earth components ``R(q) b``.
The quaternion has no singularity; it is renormalised after every integration step.

Euler angles are reported in the sign conventions of ``docs/conventions.md``, in the usual
yaw - pitch - roll order:

.. math:: R = R_z(-\\psi)\\, R_y(\\theta)\\, R_x(-\\phi)

with yaw psi positive nose right (a negative rotation about +Z up), pitch theta positive nose
up (a positive rotation about +y, since x points aft) and roll phi positive right side down (a
negative rotation about +x aft).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from slingloads.checks import positive
from slingloads.constants import G0
from slingloads.errors import InputError
from slingloads.models.multibody._jit import jit


# ----------------------------------------------------------------------- compiled helpers
@jit
def cross(a0, a1, a2, b0, b1, b2):
    """a x b for vectors given by their components.

    Parameters
    ----------
    a0, a1, a2, b0, b1, b2 : float
        Components of a and b (any units). [any unit]

    Returns
    -------
    tuple of float
        The three components of a x b (unit of a times unit of b). [unit of a x unit of b]
    """
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@jit
def dcm(q0, q1, q2, q3):
    """Rotation matrix R(q) (body to earth), row-major as a 9-tuple.

    Parameters
    ----------
    q0, q1, q2, q3 : float
        Unit quaternion. [-]

    Returns
    -------
    tuple of float
        R row by row. [-]
    """
    return (q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3, 2.0 * (q1 * q2 - q0 * q3),
            2.0 * (q1 * q3 + q0 * q2),
            2.0 * (q1 * q2 + q0 * q3), q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3,
            2.0 * (q2 * q3 - q0 * q1),
            2.0 * (q1 * q3 - q0 * q2), 2.0 * (q2 * q3 + q0 * q1),
            q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3)


@jit
def to_earth(r, b0, b1, b2):
    """R b: body components to earth components.

    Parameters
    ----------
    r : tuple of float
        R row by row (:func:`dcm`). [-]
    b0, b1, b2 : float
        Body components. [any unit]

    Returns
    -------
    tuple of float
        Earth components. [unit of the body components]
    """
    return (r[0] * b0 + r[1] * b1 + r[2] * b2, r[3] * b0 + r[4] * b1 + r[5] * b2,
            r[6] * b0 + r[7] * b1 + r[8] * b2)


@jit
def to_body(r, e0, e1, e2):
    """R^T e: earth components to body components.

    Parameters
    ----------
    r : tuple of float
        R row by row (:func:`dcm`). [-]
    e0, e1, e2 : float
        Earth components. [any unit]

    Returns
    -------
    tuple of float
        Body components. [unit of the earth components]
    """
    return (r[0] * e0 + r[3] * e1 + r[6] * e2, r[1] * e0 + r[4] * e1 + r[7] * e2,
            r[2] * e0 + r[5] * e1 + r[8] * e2)


@jit
def quaternion_rate(q0, q1, q2, q3, p, q, r):
    """dq/dt = 1/2 q (x) (0, omega), omega = (p, q, r) in body axes.

    Parameters
    ----------
    q0, q1, q2, q3 : float
        Unit quaternion. [-]
    p, q, r : float
        Body rates. [rad/s]

    Returns
    -------
    tuple of float
        dq/dt. [1/s]
    """
    return (0.5 * (-q1 * p - q2 * q - q3 * r), 0.5 * (q0 * p + q2 * r - q3 * q),
            0.5 * (q0 * q - q1 * r + q3 * p), 0.5 * (q0 * r + q1 * q - q2 * p))


# ----------------------------------------------------------------------- numpy helpers
def quaternion_from_euler(yaw, pitch, roll):
    """Unit quaternion of R = Rz(-yaw) Ry(pitch) Rx(-roll) (module conventions).

    Parameters
    ----------
    yaw, pitch, roll : array_like
        Euler angles (broadcast). [rad]

    Returns
    -------
    ndarray, shape (..., 4)
        [-]
    """
    yaw, pitch, roll = np.broadcast_arrays(*(np.asarray(a, float) for a in (yaw, pitch, roll)))
    cz, sz = np.cos(-yaw / 2), np.sin(-yaw / 2)
    cy, sy = np.cos(pitch / 2), np.sin(pitch / 2)
    cx, sx = np.cos(-roll / 2), np.sin(-roll / 2)
    return np.stack([cz * cy * cx + sz * sy * sx, cz * cy * sx - sz * sy * cx,
                     cz * sy * cx + sz * cy * sx, sz * cy * cx - cz * sy * sx], axis=-1)


def rotation_matrix(quaternion):
    """R(q), body to earth.

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Unit quaternion (body to earth). [-]

    Returns
    -------
    ndarray, shape (..., 3, 3)
        [-]
    """
    q = np.asarray(quaternion, float)
    q0, q1, q2, q3 = np.moveaxis(q, -1, 0)
    r = np.stack([q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3, 2 * (q1 * q2 - q0 * q3),
                  2 * (q1 * q3 + q0 * q2), 2 * (q1 * q2 + q0 * q3),
                  q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3, 2 * (q2 * q3 - q0 * q1),
                  2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1),
                  q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3], axis=-1)
    return r.reshape(q.shape[:-1] + (3, 3))


def euler_angles(quaternion):
    """(yaw, pitch, roll) of quaternions, module conventions.

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Unit quaternion (body to earth). [-]

    Returns
    -------
    yaw, pitch, roll : ndarray
        [rad]
    """
    r = rotation_matrix(quaternion)
    yaw = np.arctan2(-r[..., 1, 0], r[..., 0, 0])
    pitch = -np.arcsin(np.clip(r[..., 2, 0], -1.0, 1.0))
    roll = np.arctan2(-r[..., 2, 1], r[..., 2, 2])
    return yaw, pitch, roll


def quaternion_product(a, b):
    """a (x) b for quaternions (broadcasting).

    Parameters
    ----------
    a, b : array_like, shape (..., 4)
        Quaternions. [-]

    Returns
    -------
    ndarray, shape (..., 4)
        [-]
    """
    a0, a1, a2, a3 = np.moveaxis(np.asarray(a, float), -1, 0)
    b0, b1, b2, b3 = np.moveaxis(np.asarray(b, float), -1, 0)
    return np.stack([a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
                     a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
                     a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
                     a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0], axis=-1)


def conjugate(quaternion):
    """Conjugate (inverse of a unit quaternion).

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Unit quaternion (body to earth). [-]

    Returns
    -------
    ndarray, shape (..., 4)
        [-]
    """
    return np.asarray(quaternion, float) * np.array([1.0, -1.0, -1.0, -1.0])


def small_rotation(quaternion, rotation):
    """q (x) dq for rotation vectors in body axes (exact map; broadcasts over the
    rotations).

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Unit quaternion (body to earth). [-]
    rotation : array_like, shape (..., 3)
        Rotation vectors, body axes. [rad]

    Returns
    -------
    ndarray, shape (..., 4)
        [-]
    """
    phi = np.asarray(rotation, float)
    angle = np.linalg.norm(phi, axis=-1, keepdims=True)
    half = 0.5 * angle
    axis = np.divide(phi, angle, out=np.zeros_like(phi), where=angle > 0)
    d = np.concatenate([np.cos(half), np.sin(half) * axis], axis=-1)
    return quaternion_product(quaternion, d)


# ----------------------------------------------------------------------- mass properties
@dataclass(frozen=True)
class RigidBody:
    """Mass properties of the carried helicopter.

    Parameters
    ----------
    mass : float
        > 0. [kg]
    cg : array_like, shape (3,)
        Centre of gravity in airframe axes (x aft, y right, z up). [m]
    inertia : array_like, shape (3, 3)
        Inertia tensor about the CG in airframe axes (symmetric, positive definite; the
        off-diagonal entries are the tensor's, as in :class:`MassItems`). [kg m^2]
    name : str
    """

    mass: float
    cg: np.ndarray
    inertia: np.ndarray
    name: str = "HC"

    def __post_init__(self):
        object.__setattr__(self, "mass", positive(
            self.mass, f"mass of {self.name!r} must be > 0 [kg]"))
        cg = np.asarray(self.cg, float).reshape(3)
        inertia = np.asarray(self.inertia, float).reshape(3, 3)
        if not (np.all(np.isfinite(cg)) and np.all(np.isfinite(inertia))):
            raise InputError(f"CG and inertia of {self.name!r} must be finite numbers")
        if not np.allclose(inertia, inertia.T, rtol=1e-9, atol=1e-9 * np.abs(inertia).max()):
            raise InputError(f"inertia tensor of {self.name!r} must be symmetric [kg m^2]",
                             inertia.tolist())
        principal = np.linalg.eigvalsh(inertia)
        if principal[0] <= 0:
            raise InputError(f"inertia tensor of {self.name!r} must be positive definite "
                             f"(principal moments > 0) [kg m^2]", principal.tolist())
        object.__setattr__(self, "cg", cg)
        object.__setattr__(self, "inertia", 0.5 * (inertia + inertia.T))

    @classmethod
    def from_mass_items(cls, items, name="HC"):
        """Mass, CG and inertia tensor about the CG of :class:`MassItems` (own inertias plus
        parallel-axis terms).

        Parameters
        ----------
        items : MassItems
            Mass [kg], positions [m] and own inertias [kg m^2] of the items.
        name : str
            Name of the body.

        Returns
        -------
        RigidBody
        """
        return cls(items.total_mass, items.cg, items.inertia_about_cg, name)

    @property
    def weight(self):
        """m g0. [N]"""
        return self.mass * G0

    def to_frame(self):
        """Mass properties as a one-row DataFrame.

        Returns
        -------
        pandas.DataFrame
            mass [kg], CG [m], inertia tensor about the CG [kg m^2].
        """
        i = self.inertia
        return pd.DataFrame([{
            "body": self.name, "mass [kg]": self.mass, "x_cg [m]": self.cg[0],
            "y_cg [m]": self.cg[1], "z_cg [m]": self.cg[2], "Ixx [kg m^2]": i[0, 0],
            "Iyy [kg m^2]": i[1, 1], "Izz [kg m^2]": i[2, 2], "Ixy [kg m^2]": i[0, 1],
            "Ixz [kg m^2]": i[0, 2], "Iyz [kg m^2]": i[1, 2]}])
