"""RenderResult.write_exr (docs/python.md) makes the checks of `ochre render -o` (docs/cli.md, "Output
files"): a device, a FIFO, a symbolic link, a directory, a missing directory or an input of the scene (the
scene file, a mesh, a spectrum CSV, by any spelling or hard link) is refused with ochre.InputError and left
as it was, and the file is written under a temporary name and renamed, replacing only a regular file."""

import json
import os
import shutil
import stat
import tempfile
import unittest

import numpy as np

import ochre

SOURCE = os.environ["OCHRE_SOURCE_DIR"]


def scene_json():
    return {
        "camera": {"eye": [0, 0, 4], "fov": 30},
        "film": {"resolution": [8, 6]},
        "integrator": {"spp": 1},
        "materials": {"grey": {"type": "lambert", "color": {"file": "red.csv"}}},
        "lights": [{"type": "environment", "radiance": 1.0}],
        "shapes": [{"type": "sphere", "radius": 1, "material": "grey"},
                   {"type": "mesh", "file": "quad.obj", "material": "grey"}],
    }


def snapshot(path):
    """What must not change: the kind, identity, time and content of a file (a link: where it points)."""
    info = os.lstat(path)
    if stat.S_ISLNK(info.st_mode):
        return ("link", os.readlink(path), info.st_ino, info.st_mtime_ns)
    if stat.S_ISREG(info.st_mode):
        with open(path, "rb") as f:
            return ("file", f.read(), info.st_ino, info.st_mtime_ns)
    return (stat.S_IFMT(info.st_mode), info.st_ino, info.st_mtime_ns)


class WriteExr(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.path = lambda *names: os.path.join(self.dir, *names)
        shutil.copy(os.path.join(SOURCE, "tests/data/quad.obj"), self.path("quad.obj"))
        with open(self.path("red.csv"), "w") as f:
            f.write("nm,value\n380,0.1\n780,0.8\n")
        with open(self.path("scene.json"), "w") as f:
            json.dump(scene_json(), f)
        self.scene = ochre.load_scene(self.path("scene.json"))
        self.result = self.scene.render()

    def tearDown(self):
        shutil.rmtree(self.dir)

    def assertRefused(self, path, message, result=None):
        """write_exr(path) raises InputError with `message`, and leaves the path and the directory as they
        were (no temporary file)."""
        name = os.fspath(path)
        before = snapshot(name) if os.path.lexists(name) else None
        listing = sorted(os.listdir(self.dir))
        with self.assertRaises(ochre.InputError) as error:
            (result or self.result).write_exr(path)
        self.assertIn(message, str(error.exception))
        self.assertEqual(snapshot(name) if os.path.lexists(name) else None, before)
        self.assertEqual(sorted(os.listdir(self.dir)), listing)
        return str(error.exception)

    def test_a_new_file_is_written(self):
        out = self.path("out.exr")
        self.result.write_exr(out)
        channels, attributes = ochre.read_exr(out)
        self.assertTrue(np.array_equal(channels["R"], self.result.rgb[..., 0]))
        self.assertEqual(sorted(os.listdir(self.dir)), ["out.exr", "quad.obj", "red.csv", "scene.json"])

    def test_a_regular_file_is_replaced_by_renaming(self):
        out = self.path("out.exr")
        with open(out, "w") as f:
            f.write("old")
        inode = os.stat(out).st_ino
        self.result.write_exr(out)
        self.assertNotEqual(os.stat(out).st_ino, inode)  # a new file renamed over the old one
        self.assertEqual(len(ochre.read_exr(out)[0]), 3)
        self.assertFalse([n for n in os.listdir(self.dir) if ".tmp-" in n])

    def test_dev_null(self):
        self.assertRefused("/dev/null", "cannot write /dev/null: it is a character device, not a regular file")

    def test_a_fifo(self):
        fifo = self.path("out.exr")
        os.mkfifo(fifo)
        self.assertRefused(fifo, "it is a FIFO, not a regular file")
        self.assertTrue(stat.S_ISFIFO(os.lstat(fifo).st_mode))

    def test_a_symbolic_link(self):
        target = self.path("target.exr")
        with open(target, "w") as f:
            f.write("keep")
        os.symlink("target.exr", self.path("link.exr"))
        self.assertRefused(self.path("link.exr"), "it is a symbolic link to target.exr")
        with open(target) as f:
            self.assertEqual(f.read(), "keep")
        os.symlink("missing.exr", self.path("dangling.exr"))
        self.assertRefused(self.path("dangling.exr"), "it is a symbolic link")

    def test_a_directory(self):
        os.mkdir(self.path("out.exr"))
        self.assertRefused(self.path("out.exr"), "it is a directory")
        self.assertRefused(self.path("missing", "out.exr"), "does not exist")

    def test_the_scene_file_by_any_spelling(self):
        self.assertRefused(self.path("scene.json"), "it is the scene file")
        self.assertRefused(os.path.join(self.dir, ".", "..", os.path.basename(self.dir), "scene.json"),
                           "it is the scene file")
        os.link(self.path("scene.json"), self.path("hard.json"))
        self.assertRefused(self.path("hard.json"), "it is the scene file")
        import pathlib
        self.assertRefused(pathlib.Path(self.path("scene.json")), "it is the scene file")
        cwd = os.getcwd()
        os.chdir(self.dir)
        try:
            self.assertRefused("scene.json", "it is the scene file")
        finally:
            os.chdir(cwd)

    def test_the_other_inputs_of_the_scene(self):
        self.assertRefused(self.path("quad.obj"), "it is the mesh file")
        self.assertRefused(self.path("red.csv"), "it is the CSV file")

    def test_the_inputs_of_a_dict_scene(self):
        result = ochre.load_scene(scene_json(), base_dir=self.dir).render()
        self.assertRefused(self.path("quad.obj"), "it is the mesh file", result)
        self.assertRefused(self.path("red.csv"), "it is the CSV file", result)
        # The scene file of another scene is no input of this one.
        out = self.path("scene.json")
        result.write_exr(out)
        self.assertEqual(len(ochre.read_exr(out)[0]), 3)

    def test_bad_paths(self):
        with self.assertRaises(TypeError) as error:
            self.result.write_exr(3)
        self.assertEqual(str(error.exception), "path: expected a path (str or os.PathLike), got int 3")
        self.assertRefused("", "path: the path is empty")
        with self.assertRaises(ochre.InputError):
            self.result.write_exr(self.path("out\0.exr"))
        self.assertEqual(sorted(os.listdir(self.dir)), ["quad.obj", "red.csv", "scene.json"])


if __name__ == "__main__":
    unittest.main()
