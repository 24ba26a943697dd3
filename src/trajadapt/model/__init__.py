"""The data model: a case (trajectory, scene, instruction), its waypoints and the axis conventions."""
