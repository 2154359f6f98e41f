"""The planners side by side on scripted manoeuvres: runs cpbp-scenarios, keeps its rows
and reports paired statistics against C-PBP."""
