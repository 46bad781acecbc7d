# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Drop-in replacements for other Python geodesic packages, on MDCS's exact geodesics.

- :mod:`mdcs.compat.gdist`: tvb-gdist's ``gdist`` module (``import mdcs.compat.gdist as gdist``);
- :mod:`mdcs.compat.pygeodesic`: pygeodesic (``import mdcs.compat.pygeodesic.geodesic as geodesic``).

Each module documents where it deliberately differs from the original.
"""
