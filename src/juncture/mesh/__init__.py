"""Meshes of the completed airplane: assembly of the networks into one surface, checks."""
