# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The API reference is the docstrings: every public name has one (help() shows it), and the examples in them run."""

import doctest
import importlib
import inspect

import pytest

MODULES = ["mdcs", "mdcs.geodesics", "mdcs.mwt", "mdcs.variational", "mdcs.silhouettes", "mdcs.min_cut", "mdcs.io",
           "mdcs.dask", "mdcs.compat.gdist", "mdcs.compat.pygeodesic", "mdcs.compat.pygeodesic.geodesic"]


@pytest.mark.parametrize("name", MODULES)
def test_every_public_name_is_documented(name):
    module = importlib.import_module(name)
    assert inspect.getdoc(module)
    for item in module.__all__:
        obj = getattr(module, item)
        if inspect.isclass(obj) or inspect.isfunction(obj):
            assert inspect.getdoc(obj), f"{name}.{item} has no docstring"
        if inspect.isclass(obj):
            for member, value in vars(obj).items():
                if not member.startswith("_") and (inspect.isfunction(value) or isinstance(value, property)):
                    assert inspect.getdoc(value) or isinstance(value, property), f"{name}.{item}.{member}"


@pytest.mark.parametrize("name", ["mdcs.geodesics", "mdcs.mwt", "mdcs.min_cut", "mdcs.variational"])
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    failures, tried = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert tried > 0 and failures == 0
