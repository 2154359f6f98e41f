"""The tools read the native settings schema, and an entry added to it reaches them."""

import json
import tempfile
import unittest
from pathlib import Path

from cpbp_experiment import configs, settings


class SettingsSchemaTest(unittest.TestCase):
    def test_the_trajectory_range_is_the_schemas(self):
        trajectories = settings.SETTINGS["trajectories"]
        self.assertEqual((configs.MIN_TRAJECTORIES, configs.MAX_TRAJECTORIES),
                         tuple(int(n) for n in trajectories.range[:2]))
        self.assertIn(trajectories.default, trajectories.offered)

    def test_every_default_is_a_value_its_setting_may_hold(self):
        for setting in settings.SETTINGS.values():
            setting.check(setting.default)

    def test_values_of_another_type_or_out_of_range_are_refused(self):
        horizon = settings.SETTINGS["horizon"]
        horizon.check(1)
        with self.assertRaisesRegex(ValueError, "within 0.2–3 s"):
            horizon.check(9.0)
        with self.assertRaisesRegex(ValueError, "takes a number"):
            horizon.check(True)
        with self.assertRaisesRegex(ValueError, "takes a whole number"):
            settings.SETTINGS["trajectories"].check(2.5)
        with self.assertRaisesRegex(ValueError, "one of auto, low, medium, high"):
            settings.SETTINGS["graphics_quality"].check("ultra")

    def test_a_throwaway_entry_in_the_schema_reaches_the_tools(self):
        schema = json.loads(settings.SCHEMA_FILE.read_text("utf-8"))
        schema["settings"].append({
            "name": "throwaway", "label": "Throwaway", "description": "A test's.",
            "unit": "cm", "type": "float", "default": 2.5, "owner": "planner",
            "player": True, "menu": "Planner", "range": [0.0, 10.0, 0.5]})
        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder) / "settings.json"
            path.write_text(json.dumps(schema), "utf-8")
            throwaway = settings.load(path)["throwaway"]
        self.assertEqual((throwaway.default, throwaway.range), (2.5, (0.0, 10.0, 0.5)))
        with self.assertRaises(ValueError):
            throwaway.check(11.0)


if __name__ == "__main__":
    unittest.main()
