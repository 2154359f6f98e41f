"""Counter-Steer's headless experiment: the thesis's automatic test (Figure 5.1) and
frame-rate study (Figure 5.2), run by Godot workers on the game's own test level."""
