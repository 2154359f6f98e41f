"""A folder of rows ridden with the learned cost-to-go keeps the network's identity and
refuses rows of another (cpbp_experiment/value_model.py)."""

import tempfile
import unittest
from pathlib import Path

from cpbp_experiment.value_model import RECORD, identity, keep_value_record, uses_value


class ValueRecordTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = Path(self.tmp.name)
        (self.root / "models").mkdir()
        self.model = self.root / "models" / "value-dirt_125.safetensors"
        self.model.write_bytes(b"first network")
        self.out = self.root / "rows"

    def tearDown(self):
        self.tmp.cleanup()

    def test_only_settings_that_turn_it_on_are_recorded(self):
        self.assertTrue(uses_value({"terminal_value": "true", "value_horizon": "0.6"}))
        self.assertTrue(uses_value({"terminal_value": "True"}))
        self.assertFalse(uses_value({"terminal_value": "false"}))
        self.assertFalse(uses_value({"horizon": "0.6"}))
        self.assertEqual(keep_value_record(self.out, self.root, "dirt_125", {"horizon": "0.6"}),
                         "")
        self.assertFalse((self.out / RECORD).exists())

    def test_a_folder_keeps_its_networks_identity_and_refuses_another(self):
        on = {"terminal_value": "true"}
        first = keep_value_record(self.out, self.root, "dirt_125", on)
        self.assertEqual(first, identity(self.model))
        self.assertEqual(len(first), 12)
        self.assertEqual((self.out / RECORD).read_text().strip(), first)
        self.assertEqual(keep_value_record(self.out, self.root, "dirt_125", on), first,
                         "the same network resumes")
        self.model.write_bytes(b"retrained network")
        with self.assertRaisesRegex(ValueError, f"superseded/value-{first}"):
            keep_value_record(self.out, self.root, "dirt_125", on)
        self.assertEqual((self.out / RECORD).read_text().strip(), first, "record kept")

    def test_a_bike_without_a_network_is_recorded_as_none(self):
        on = {"terminal_value": "1"}
        self.assertEqual(keep_value_record(self.out, self.root, "sport_600", on), "none")
        with self.assertRaisesRegex(ValueError, "is now"):
            keep_value_record(self.out, self.root, "dirt_125", on)


if __name__ == "__main__":
    unittest.main()
