"""The benchmark bicycle (Meijaard et al. 2007) ridden by the game's physics and compared
with the paper's linear model, computed by the `bicycleparameters` package: see
docs/physics.md, "The benchmark bicycle"."""
