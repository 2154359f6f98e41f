class_name BodyworkPiece
extends Resource
## One piece of a bike's bodywork (a tank, a seat, a frame rail), authored in the frame of
## the bike its BikeBodywork was drawn on (x forward, y up, z right, origin on the ground
## midway between the wheels; metres) and carried by the bike's frame body.

## ROUNDED: a box with rounded edges (RoundedBox), placed and sized as a box.
enum Shape { BOX, ELLIPSOID, ROD, ROUNDED }

@export var shape := Shape.BOX
## Which BikeLooks material it is made of ("paint" takes the bike's own colour).
@export var look := "paint"
## A box's or an ellipsoid's centre, or a rod's first end.
@export var from := Vector3.ZERO
## A rod's second end (unused by boxes and ellipsoids).
@export var to := Vector3.ZERO
## A box's or an ellipsoid's extent along the bike's forward, up and right axes.
@export var size := Vector3(0.1, 0.1, 0.1)
## A rod's radius.
@export var radius := 0.02
## A box's nose-up tilt (radians, about the bike's right).
@export var pitch := 0.0
## Drawn twice: as authored and mirrored to the bike's other side.
@export var mirrored := false
