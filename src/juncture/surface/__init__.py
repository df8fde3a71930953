"""The completed airplane's surface, as the next tool takes it.

==========================  ==================================================================
``networks``                TM-4406's juncture blocks (4 or 6) and their orientation
``body_split``              TM-4607's fuselage split by theta_b(x) through the touching parts
``component_networks``      the other components' networks, trimmed at their intersections
``assemble``                one triangulated surface of every network, both halves
``seams``, ``imprint``      seams whose sides differ; footprints cut into their hosts
``chart``, ``remesh``       conformal charts; re-triangulation for angles, seams kept shared
``mirror``                  both halves triangulated once: a surface's image copies it
``pipeline``                ``juncture.mesh``: assemble, check, re-triangulate
``quality``, ``check``      closed, manifold, oriented, no crossing; volume, wetted area, angles
``write``                   STL, Gmsh, VTU with component ids
``solids``                  CAD solids: one per component, or the fused airplane (STEP, IGES)
==========================  ==================================================================
"""
