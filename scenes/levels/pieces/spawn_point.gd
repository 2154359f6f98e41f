@tool
class_name SpawnPoint
extends Marker3D
## Where the bike can start or respawn: the bike stands on the ground below this point,
## facing this node's −z. LB/RB (Q/E) cycle through a level's spawn points in tree order.
## The editor plugin draws the bike's outline here.

## Shown in the HUD when the player respawns here.
@export var label := ""


## The bike's spawn transform: this point's position and heading, upright.
func spawn_transform() -> Transform3D:
	var forward := -global_basis.z
	forward.y = 0.0
	if forward.length() < 1e-3:
		forward = Vector3.FORWARD
	return Transform3D(Basis.looking_at(forward.normalized(), Vector3.UP), global_position)
