import json
import subprocess
import tempfile
import unittest
from pathlib import Path

from cpbp_experiment.fingerprint import (COMPARED, UNRECORDED, FingerprintError, PlatformStore,
                                         code_identity, differences, identity, refusal)

MACHINE = {key: f"{key} value" for key in COMPARED} | {"commit": "abc", "cores": "2"}


class FingerprintTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.root = Path(self.directory.name)

    def tearDown(self):
        self.directory.cleanup()

    def test_the_identity_follows_what_decides_a_ride_not_the_commit(self):
        self.assertEqual(identity(MACHINE), identity(MACHINE | {"commit": "def", "cores": "4"}))
        for key in COMPARED:
            self.assertNotEqual(identity(MACHINE), identity(MACHINE | {key: "other"}), key)

    def test_differences_name_each_field_that_changed(self):
        now = MACHINE | {"c_library": "glibc 2.44", "math_path": "baseline"}
        self.assertEqual(differences(MACHINE, now), [
            "c_library: c_library value → now glibc 2.44",
            "math_path: math_path value → now baseline",
        ])

    def test_rows_of_this_platform_mix_with_nothing(self):
        self.assertEqual(refusal({identity(MACHINE)}, MACHINE, {}, Path("r.csv")), "")

    def test_rows_of_another_or_an_unrecorded_platform_are_refused_with_reasons(self):
        older = MACHINE | {"godot": "4.6.2"}
        known = {identity(older): older}
        text = refusal({identity(older), UNRECORDED, identity(MACHINE)}, MACHINE, known,
                       Path("r.csv"))
        self.assertIn("godot: 4.6.2 → now godot value", text)
        self.assertIn("before platforms were recorded", text)
        self.assertIn("--allow-mixed", text)

    def test_the_store_keeps_each_identity_once_and_survives_rereading(self):
        store = PlatformStore(self.root / "platforms.json")
        name = store.add(MACHINE)
        self.assertEqual(store.add(MACHINE | {"commit": "later"}), name)
        self.assertEqual(store.load(), {name: MACHINE}, "the first commit stays")
        self.assertFalse((self.root / "platforms.json.tmp").exists())

    def test_a_corrupt_store_is_an_error_not_a_crash(self):
        (self.root / "platforms.json").write_text("{not json")
        with self.assertRaisesRegex(FingerprintError, "unreadable"):
            PlatformStore(self.root / "platforms.json").load()
        (self.root / "platforms.json").write_text(json.dumps({"a": 3}))
        with self.assertRaisesRegex(FingerprintError, "not a map"):
            PlatformStore(self.root / "platforms.json").load()

    def test_the_code_identity_changes_with_an_uncommitted_change_to_riding_code(self):
        def git(*arguments):
            subprocess.run(["git", "-C", str(self.root), *arguments], check=True,
                           capture_output=True)
        git("init", "-q")
        for path in ("native/a.rs", "scenes/a.gd", "scripts/b.gd",
                     "addons/cpbp/cpbp.gdextension", "project.godot", "models/m.safetensors",
                     "docs/x.md"):
            (self.root / path).parent.mkdir(parents=True, exist_ok=True)
            (self.root / path).write_text("1\n")
        git("add", ".")
        git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "x")
        clean = code_identity(self.root)
        self.assertRegex(clean, "^[0-9a-f]{16}$")
        (self.root / "docs/x.md").write_text("2\n")
        self.assertEqual(code_identity(self.root), clean, "documentation does not ride")
        (self.root / "native/a.rs").write_text("2\n")
        changed = code_identity(self.root)
        self.assertTrue(changed.startswith(clean + "+uncommitted-"), changed)
        (self.root / "scenes/new.gd").write_text("3\n")
        self.assertNotEqual(code_identity(self.root), changed, "new files count too")


if __name__ == "__main__":
    unittest.main()
