"""The Gazebo backend's parts: merged plant meshes, SDF elements, ground truth."""
