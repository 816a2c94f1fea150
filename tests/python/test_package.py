"""The package: pure-Python modules around the private extension pagor._pagor, its stubs and
py.typed; signatures and docstrings that tell the truth; short TypeErrors."""
import ast
import inspect
from pathlib import Path

import numpy as np
import pytest

import pagor
from conftest import SOURCE_DIR

PUBLIC = ["register", "register_correspondences", "read_cloud", "synthetic_scene",
          "default_config", "preset_config", "preset_names", "check_config"]


def test_pagor_is_a_package_around_a_private_extension():
    package = Path(pagor.__file__).parent
    assert pagor.__file__.endswith("__init__.py")
    assert (package / "py.typed").exists()
    assert (package / "_pagor.pyi").exists()
    assert Path(pagor._pagor.__file__).parent == package
    assert pagor._pagor.__name__ == "pagor._pagor"
    assert pagor.__version__ == pagor._pagor.__version__ and pagor.__version__.count(".") == 2


def test_the_stubs_name_every_function_of_the_extension():
    stub = ast.parse((Path(pagor.__file__).parent / "_pagor.pyi").read_text())
    stubbed = {node.name for node in stub.body
               if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    defined = {name for name in dir(pagor._pagor) if not name.startswith("_")}
    assert stubbed == defined


@pytest.mark.parametrize("name", PUBLIC)
def test_public_functions_have_signatures_with_named_parameters(name):
    function = getattr(pagor, name)
    signature = inspect.signature(function)
    assert "handle" not in str(signature)
    assert function.__doc__ and len(function.__doc__) > 20


def test_register_signature_is_the_documented_one():
    parameters = inspect.signature(pagor.register).parameters
    assert list(parameters) == ["source", "target", "source_labels", "target_labels", "config",
                                "ground_truth", "threads"]
    assert parameters["ground_truth"].kind is inspect.Parameter.KEYWORD_ONLY
    assert parameters["threads"].default == 1
    parameters = inspect.signature(pagor.register_correspondences).parameters
    assert list(parameters) == ["p", "q", "weights", "config", "source", "target",
                                "ground_truth", "threads"]


def test_every_public_property_has_a_docstring():
    # Properties and the report's keys (read-only data descriptors), inherited ones too.
    counts = {}
    for cls in (pagor.Result, pagor.Level, pagor.Landmarks, pagor.Correspondences):
        assert cls.__doc__
        counts[cls.__name__] = 0
        for name, member in inspect.getmembers(cls):
            if name.startswith("_") or not inspect.isdatadescriptor(member):
                continue
            counts[cls.__name__] += 1
            assert member.__doc__, f"{cls.__name__}.{name} has no docstring"
    assert counts == {"Result": 14, "Level": 14, "Landmarks": 1, "Correspondences": 1}


def test_a_result_pickled_before_the_report_moved_to_data_still_loads():
    rng = np.random.default_rng(3)
    p = rng.uniform(-20, 20, (60, 3))
    result = pagor.register_correspondences(p, p + [1.0, 2.0, 0.0])
    state = dict(vars(result))
    state["_report"] = state.pop("_data")  # as 0.1 before pickled it
    old = pagor.Result.__new__(pagor.Result)
    old.__setstate__(state)
    assert old == result and old.selected_level == result.selected_level
    level_state = {"_level": result.levels[0].to_dict(), "clique": result.levels[0].clique}
    level = pagor.Level.__new__(pagor.Level)
    level.__setstate__(level_state)
    assert level == result.levels[0]


def test_report_attributes_are_read_only():
    rng = np.random.default_rng(3)
    p = rng.uniform(-20, 20, (60, 3))
    result = pagor.register_correspondences(p, p + [1.0, 2.0, 0.0])
    assert result.selected_level is not None
    with pytest.raises(AttributeError):
        result.selected_level = 1
    with pytest.raises(AttributeError):
        result.levels[0].epsilon = 1.0


def test_the_docstrings_say_what_the_defaults_are():
    assert pagor.default_config()["label_scheme"] == "auto"
    assert "(default ``auto``" in pagor.register.__doc__
    assert "semantickitti-train" not in pagor.register.__doc__
    # accepted is False (not None) without clouds, as the docstring says
    assert "False when there were no clouds" in pagor.Result.accepted.__doc__
    assert "pagor.register/1" in pagor.Result.to_json.__doc__


CLOUD = np.random.default_rng(3).uniform(-20, 20, (500, 3)).astype(np.float32)


def test_a_mistyped_keyword_is_a_short_type_error():
    with pytest.raises(TypeError) as error:
        pagor.register(CLOUD, CLOUD, groundtruth=np.eye(4))
    message = str(error.value)
    assert "groundtruth" in message and len(message) < 120, message
    with pytest.raises(TypeError) as error:
        pagor.register_correspondences(CLOUD, CLOUD, weight=np.ones(500))
    assert "weight" in str(error.value) and len(str(error.value)) < 120


@pytest.mark.parametrize("call,message", [
    (lambda: pagor.register(CLOUD, CLOUD, threads="2"), "threads: expected an int, got str"),
    (lambda: pagor.register(CLOUD, CLOUD, threads=2.0), "threads: expected an int, got float"),
    (lambda: pagor.register(CLOUD, CLOUD, config=[("graph", {})]),
     "config: expected a dict .* got list"),
    (lambda: pagor.register_correspondences(CLOUD, CLOUD, config="x"), "config: expected a dict"),
    (lambda: pagor.read_cloud(3), r"path: expected a path \(str, bytes or os.PathLike\), got int"),
    (lambda: pagor.synthetic_scene("7"), "seed: expected an int, got str"),
    (lambda: pagor.preset_config(None), "name: expected a str, got NoneType"),
    (lambda: pagor.check_config(None), "config: expected a dict"),
])
def test_a_wrong_type_is_a_short_type_error_naming_the_argument(call, message):
    with pytest.raises(TypeError, match=message) as error:
        call()
    assert len(str(error.value)) < 120


@pytest.mark.parametrize("call,message", [
    (lambda: pagor.register(CLOUD, CLOUD, threads=2**40), "threads: expected at most"),
    (lambda: pagor.synthetic_scene(-1), r"seed: expected 0 .. 2\*\*64 - 1, got -1"),
])
def test_a_value_out_of_range_is_a_value_error_naming_the_argument(call, message):
    with pytest.raises(ValueError, match=message):
        call()
