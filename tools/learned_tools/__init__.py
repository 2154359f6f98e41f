"""The learned controller's tools: its report (`report`, docs/learned/training.md) and
the upkeep of its committed evaluation (`evaluation`). `make train` runs both."""
