"""Terrains from Python: batch point queries and wheel contacts over NumPy arrays equal the C++ answers
(wtc_python_query_reference: every piece queried, no index), and bad arrays are refused by name."""
import os
import subprocess

import numpy as np
import pytest

import wtc

REACH = 0.5     # m
RADIUS = 0.19   # m, the robot's wheel
WIDTH = 0.12    # m
N = 400


def reference(terrain_file, points, axles, tmp_path):
    table = tmp_path / "points.txt"
    np.savetxt(table, np.hstack([points, axles]), fmt="%.17g")
    out = tmp_path / "reference.txt"
    subprocess.run([os.environ["WTC_QUERY_REFERENCE"], str(terrain_file), str(table), repr(REACH), repr(RADIUS),
                    repr(WIDTH), str(out)], check=True)
    queries, contacts = [], []
    for line in out.read_text().splitlines():
        words = line.split()
        if words[0] == "contact":
            contacts.append([float(w) for w in words[1:]])
        else:
            queries.append([float(w) for w in words])
    return np.array(queries), np.array(contacts).reshape(-1, 6)


def sample(terrain, seed):
    """Points over the terrain's box, from 0.3 m below its top to 0.4 m above: inside pieces, near them, beyond
    reach."""
    rng = np.random.default_rng(seed)
    low, high = np.array(terrain.bounds[0]), np.array(terrain.bounds[1])
    points = rng.uniform(low, high, size=(N, 3))
    points[:, 2] = rng.uniform(high[2] - 0.3, high[2] + 0.4, size=N)
    axles = rng.normal(size=(N, 3))
    axles[:, 1] += 3.0  # mostly along y, some cambered
    return points, axles


@pytest.mark.parametrize("name, seed", [("terrains/rough_ground.yaml", 1), ("terrains/ledge.yaml", 2)])
def test_batch_queries_equal_the_cpp_ones(source_dir, tmp_path, name, seed):
    terrain = wtc.load_terrain(source_dir / name)
    points, axles = sample(terrain, seed)
    expected, expected_contacts = reference(source_dir / name, points, axles, tmp_path)

    distances, normals, pieces = terrain.query(points, max_distance=REACH)
    assert distances.shape == (N,) and normals.shape == (N, 3) and pieces.shape == (N,)
    np.testing.assert_array_equal(pieces, expected[:, 4].astype(int))
    np.testing.assert_allclose(distances, expected[:, 0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(normals, expected[:, 1:4], rtol=0, atol=1e-12)
    # Both sides of the reach and of the surface are in the sample.
    assert np.isinf(distances).any() and (distances < 0).any() and (distances > 0).any()
    assert (pieces[np.isinf(distances)] == -1).all()

    contacts = terrain.wheel_contacts(points, axles, radius=RADIUS, width=WIDTH)
    assert len(contacts["index"]) == len(expected_contacts) > 0
    np.testing.assert_array_equal(contacts["index"], expected_contacts[:, 0].astype(int))
    np.testing.assert_allclose(contacts["ground_point"], expected_contacts[:, 1:4], rtol=0, atol=1e-12)
    np.testing.assert_allclose(contacts["deflection"], expected_contacts[:, 4], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(contacts["piece"], expected_contacts[:, 5].astype(int))


def test_a_built_heightfield_is_queried_like_its_flat_ground():
    # Inside the ground the distance is minus the depth in the nearest piece: the point below is nearer the top
    # (0.05 m) than its prism's other faces (>= 0.12 m).
    terrain = wtc.heightfield(np.zeros((5, 7)), spacing_x=0.5, spacing_y=0.5, origin=(-1.5, -1.0, 0.2))
    assert terrain.piece_count == 2 * 4 * 6
    points = np.array([[0.0, 0.0, 0.7], [0.35, -0.38, 0.15], [0.1, 0.1, 0.2 + 1e-3]])
    distances, normals, pieces = terrain.query(points)
    np.testing.assert_allclose(distances, [0.5, -0.05, 1e-3], atol=1e-12)
    np.testing.assert_allclose(normals, [[0, 0, 1]] * 3, atol=1e-12)
    assert (pieces >= 0).all()


def test_bad_arrays_are_refused_naming_the_problem():
    terrain = wtc.heightfield(np.zeros((3, 3)))
    with pytest.raises(wtc.InvalidInputError, match=r"points must be an array of shape \(N, 3\), not \(4, 2\)"):
        terrain.query(np.zeros((4, 2)))
    with pytest.raises(wtc.InvalidInputError, match=r"point \(nan, 0, 1\) is not finite"):
        terrain.query(np.array([[np.nan, 0.0, 1.0]]))
    with pytest.raises(wtc.InvalidInputError, match="max_distance"):
        terrain.query(np.zeros((1, 3)), max_distance=np.inf)
    with pytest.raises(wtc.InvalidInputError, match="free_radius"):
        terrain.wheel_contacts(np.zeros((1, 3)), np.array([[0.0, 1.0, 0.0]]), radius=-1.0)


def test_a_dem_written_and_loaded_is_the_same_ground(tmp_path):
    """wtc.write_dem then wtc.load_terrain: the GeoTIFF's ground is the array's, cropped and placed as asked;
    a NaN sample leaves a hole; a .npy array loads with its spacing."""
    rows, cols, spacing = 40, 60, 0.05
    y, x = np.mgrid[0:rows, 0:cols] * spacing
    full = 0.1 * np.sin(x) + 0.05 * y  # row 0 is the south edge, as in wtc.heightfield
    heights = full.copy()
    heights[10, 10] = np.nan
    path = tmp_path / "dem.tif"
    wtc.write_dem(path, heights, spacing, south_west=(350000.0, 600000.0), epsg=32633)

    whole = wtc.load_terrain(path)
    same = wtc.heightfield(full, spacing, spacing)
    # Two points above the ground, one 1 cm under it where the NaN sample (0.5, 0.5) took its four cells.
    under = 0.1 * np.sin(0.515) + 0.05 * 0.52 - 0.01  # within 0.5 mm of the surface's plane there
    points = np.array([[1.0, 1.0, 1.0], [2.5, 1.5, 1.0], [0.515, 0.52, under]])
    distances, _, _ = whole.query(points, max_distance=2.0)
    expected, _, _ = same.query(points, max_distance=2.0)
    np.testing.assert_allclose(distances[:2], expected[:2], rtol=0, atol=1e-6)  # float32 heights
    assert expected[2] < 0 < distances[2]  # inside the full ground, in the air of the hole

    part = wtc.load_terrain(path, crop=(350001.0, 600000.5, 350002.0, 600001.0), frame="map",
                            translation=(-350000.0, -600000.0, 0.0))
    (low, high) = part.bounds
    np.testing.assert_allclose([low[0], low[1], high[0], high[1]], [1.0, 0.5, 2.0, 1.0], atol=1e-6)
    assert part.piece_count == 2 * 20 * 10

    np.save(tmp_path / "dem.npy", heights[::-1])  # a .npy is a map: its first row is north
    from_npy = wtc.load_terrain(tmp_path / "dem.npy", spacing=spacing)
    distances_npy, _, _ = from_npy.query(points[:2], max_distance=2.0)
    np.testing.assert_allclose(distances_npy, expected[:2], rtol=0, atol=1e-12)

    with pytest.raises(wtc.Error, match="the raster has no georeferencing: give spacing"):
        wtc.load_terrain(tmp_path / "dem.npy")
    with pytest.raises(wtc.Error, match="the DEM arguments are for a raster"):
        wtc.load_terrain(tmp_path / "t.yaml", step=2)
