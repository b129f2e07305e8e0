#!/usr/bin/env python3
"""Writes and verifies the worked examples of proofs/examples/ (certificate formats 1 to 6).

Every scene and certificate is written from the tables below, then read back from disk and checked
by a small exact checker written here with Python's fractions (a second implementation, independent
of the C++ one): each *.valid.json must pass, each *.invalid.json must fail for the reason its
table entry names. Run from anywhere:  python3 proofs/examples/make_examples.py
"""
import itertools
import json
import math
import os
import re
import sys
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))

# ----------------------------------------------------------------------------------------------
# Scenes (numbers are written as they should appear in the file)

# The block in a corner (theory.md section 9) with friction mu = 1/2 at every contact.
CORNER_MU_1_2 = [
    {"at": [0, 0], "normal": [0, 1], "mu": "1/2", "name": "floor, left"},
    {"at": [1, 0], "normal": [0, 1], "mu": "1/2", "name": "floor, right"},
    {"at": [0, 0], "normal": [1, 0], "mu": 0.5, "name": "wall, bottom"},
    {"at": [0, 1], "normal": [1, 0], "mu": "5e-1", "name": "wall, top"},
]

# The fixtures of section 7 (shared parts).
LEGS = [[1, 1], [-1, 1], [-1, -1], [1, -1]]
PIN = [{"at": [-1, 0], "normal": [1, 0], "name": "pin"}]
SQUARE_BODY = {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "com": [0, 0]}
FIXTURE = {"wrenchkit": 1, "body": SQUARE_BODY, "contacts": PIN,
           "support": {"mu": "1/2", "points": [{"at": at, "force": "1/4"} for at in LEGS]}}
TABLE_PINNED = {"wrenchkit": 1, "body": SQUARE_BODY, "contacts": PIN,
                "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": at} for at in LEGS]}}

MAT_LEGS = {"wrenchkit": 1, "support": {"mu": "1/2", "weight": 5, "pressure_center": [0, 0],
                                      "points": [{"at": [-2, 0]}, {"at": [0, 0]}, {"at": [2, 0]}],
                                      "regions": [{"outline": [["-1/2", "-1/2"], ["1/2", "-1/2"], ["1/2", "1/2"],
                                                               ["-1/2", "1/2"]], "pressure": "uniform", "force": 1}]}}
SQUARE_OUTLINE = {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}
CORNERS = [[-1, -1], [1, -1], [1, 1], [-1, 1]]
SQUARE_REGION = {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform", "force": 1}

FENCE = {"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]]},
         "support": {"mu": "1/2", "points": [{"at": [-1, -1], "force": 1}, {"at": [1, -1], "force": 1},
                                             {"at": [1, 1], "force": 1}, {"at": [-1, 1], "force": 1}]}}
FENCE_PUSHER = {"segment": [["-1/2", -1], ["1/2", -1]], "normal": [0, 1], "mu": "1/2"}

SCENES = {
    "l_part": {"wrenchkit": 1, "name": "an L-shaped part for three fingers (no contacts)", "body": {"outline": [[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]}},
    "square_part": {"wrenchkit": 1, "name": "the unit square as a part for two fingers (no contacts)", "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]]}},
    "square_side_middles": {"wrenchkit": 1, "name": "the square held at its side middles, mu = 1/10 (GraspIt!'s torque scale 1/sqrt 2)", "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "com": [0, 0]}, "contacts": [{"at": [0, -1], "normal": [0, 1], "mu": "1/10"}, {"at": [0, 1], "normal": [0, -1], "mu": "1/10"}, {"at": [-1, 0], "normal": [1, 0], "mu": "1/10"}, {"at": [1, 0], "normal": [-1, 0], "mu": "1/10"}]},
    "two_fingers_offset_own_mu": {"wrenchkit": 1, "name": "the offset fingers with their own friction, mu = 1 and 3/4: closed while both keep more than 2/3 of it", "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1, "name": "left finger"}, {"at": [1, 1], "normal": [-1, 0], "mu": "3/4", "name": "right finger"}]},
    "two_fingers_offset_moment": {"wrenchkit": 1, "name": "the offset fingers against a pure moment: balanced only above mu = 1/2", "contacts": [{"at": [-1, 0], "normal": [1, 0], "name": "left finger"}, {"at": [1, 1], "normal": [-1, 0], "name": "right finger"}], "load": {"wrench": [0, 0, 1]}},
    "two_fingers_offset": {"wrenchkit": 1, "name": "two fingers at (-1, 0) and (1, 1), normals (1, 0) and (-1, 0): the contact line at tan 1/2", "contacts": [{"at": [-1, 0], "normal": [1, 0], "name": "left finger"}, {"at": [1, 1], "normal": [-1, 0], "name": "right finger"}]},
    "three_contacts_chirotope": {"wrenchkit": 1, "name": "three contacts whose closure threshold 7/2 is proved by the 3x3 minors alone (a moment changes sign at 31/8)", "contacts": [{"at": [-4, -3], "normal": [-5, 4]}, {"at": [-2, 4], "normal": [-4, 0]}, {"at": [-4, -3], "normal": [-2, 4]}]},
    "ladder_gravity": {"wrenchkit": 1, "name": "the leaning square (ladder) of theory.md section 9 under its weight", "body": {"outline": [["0", "0"], ["3", "4"], ["-1", "7"], ["-4", "3"]], "com": ["-1/2", "7/2"]}, "contacts": [{"at": ["0", "0"], "normal": ["0", "1"], "name": "floor"}, {"at": ["-4", "3"], "normal": ["1", "0"], "name": "wall"}], "load": {"gravity": 1}},
    "two_fingers_same_way": {"wrenchkit": 1, "name": "two fingers pushing the same way, and a load along it", "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 1], "normal": [1, 0]}], "load": {"force": [1, 0], "at": [0, 0]}},
    "two_fingers_mu1": {
        "wrenchkit": 1,
        "name": "two fingers at (-1, 0) and (1, 0) pressing inward, mu = 1: the edges are alternate corners of the cube",
        "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1, "name": "left finger"},
                     {"at": [1, 0], "normal": [-1, 0], "mu": 1, "name": "right finger"}],
    },
    "two_fingers_mu0": {
        "wrenchkit": 1,
        "name": "the same two fingers without friction: not in force closure",
        "contacts": [{"at": [-1, 0], "normal": [1, 0], "name": "left finger"},
                     {"at": [1, 0], "normal": [-1, 0], "name": "right finger"}],
    },
    "block_corner_mu0": {
        "wrenchkit": 1,
        "name": "frictionless unit block in a corner (certificate-format.md section 5)",
        "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]], "com": ["1/2", "1/2"]},
        "contacts": [
            {"at": [0, 0], "normal": [0, 1], "name": "floor, left"},
            {"at": [1, 0], "normal": [0, 1], "name": "floor, right"},
            {"at": [0, 0], "normal": [1, 0], "name": "wall, bottom"},
            {"at": [0, 1], "normal": [1, 0], "mu": 0, "name": "wall, top"},
        ],
        "load": {"force": [0, -1], "at": ["1/2", "1/2"]},
    },
    "square_crossed_couples": {
        "wrenchkit": 1,
        "name": "square [0,2]^2 held by two crossed couples, frictionless (certificate-format.md section 5)",
        "body": {"outline": [[0, 0], [2, 0], [2, 2], [0, 2]]},
        "contacts": [
            {"at": ["3/2", 0], "normal": [0, 1], "name": "bottom"},
            {"at": ["1/2", 2], "normal": [0, -1], "name": "top"},
            {"at": [0, "3/2"], "normal": [1, 0], "name": "left"},
            {"at": [2, "1/2"], "normal": [-1, 0], "name": "right"},
        ],
    },
    "two_finger_mu_1_2": {
        "wrenchkit": 1,
        "name": "unit square pinched by two fingers with mu = 1/2 (theory.md section 8.5)",
        "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]]},
        "contacts": [
            {"at": [0, "1/2"], "normal": [1, 0], "mu": "1/2", "name": "finger 1"},
            {"at": [1, 0.5], "normal": [-1, 0], "mu": 0.5, "name": "finger 2"},
        ],
    },
    "triangle_mu_1_10": {
        "wrenchkit": 1,
        "name": "triangle made secure by friction, mu = 1/10 (theory.md section 8.7); mixed number forms",
        "body": {"outline": [[0, 0], [6, 0], [0, 6]], "com": [2, 2]},
        "contacts": [
            {"at": [1, 0], "normal": ["0", "1e0"], "mu": 0.1},
            {"at": ["0.0", "1."], "normal": ["+1/1", 0], "mu": "1e-1"},
            {"at": ["3.0", "30E-1"], "normal": ["-1", "-.1e1"], "mu": "1/10"},
        ],
        "load": {"gravity": 1},
        "support": {"mu": "1/2", "points": [{"at": [2, 2], "force": 1}]},
    },
    # theory.md section 9: the block in a corner with mu = 1/2 at all four contacts, under four loads
    "block_corner_mu_1_2_gravity": {
        "wrenchkit": 1,
        "name": "unit block in a corner, mu = 1/2, weight 1 at the centre (theory.md section 9): balanced",
        "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]], "com": ["1/2", 0.5]},
        "contacts": CORNER_MU_1_2,
        "load": {"gravity": 1},
    },
    "block_corner_mu_1_2_push": {
        "wrenchkit": 1,
        "name": "unit block in a corner, mu = 1/2, pushed by (-1,0) at (1,1/2) (theory.md section 9): balanced",
        "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]], "com": ["1/2", "1/2"]},
        "contacts": CORNER_MU_1_2,
        "load": {"force": [-1, 0], "at": [1, "1/2"]},
    },
    "block_corner_mu_1_2_pull": {
        "wrenchkit": 1,
        "name": "unit block in a corner, mu = 1/2, pulled by (1,0) at (0,1/2) (theory.md section 9): not balanced",
        "body": {"outline": [[0, 0], [1, 0], [1, 1], [0, 1]]},
        "contacts": CORNER_MU_1_2,
        "load": {"at": [0, "0.5"], "force": ["1", 0]},
    },
    "block_corner_mu_1_2_torque": {
        "wrenchkit": 1,
        "name": "unit block in a corner, mu = 1/2, a counter-clockwise couple 1 (a wrench load): not balanced",
        "contacts": CORNER_MU_1_2,
        "load": {"wrench": [0, 0, "1"]},
    },
    "wrench_generators": {
        "wrenchkit": 1,
        "name": "four wrench generators that positively span R^3",
        "contacts": [
            {"wrench": [1, 0, 0], "name": "push +x"},
            {"wrench": [0, "1", 0], "name": "push +y"},
            {"wrench": [0, 0, "1e0"], "name": "counter-clockwise torque"},
            {"wrench": [-1, -1, -1]},
        ],
    },
    # Sliding (certificate-format.md section 6): the four-legged table of theory-sliding.md section 6,
    # every leg's force unknown, and a barbell whose two forces are given.
    "table_four_legs": {
        "wrenchkit": 1,
        "name": "four-legged table, legs (+-1,+-1), mu = 1, W = 1, every leg force unknown (theory-sliding.md 6)",
        "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "com": [0, 0]},
        "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0],
                    "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]},
    },
    "barbell_known": {
        "wrenchkit": 1,
        "name": "barbell, forces 1/2 at (0,-1) and (0,1), mu = 1/2 (a known distribution)",
        "support": {"mu": "1/2", "points": [{"at": [0, -1], "force": "1/2"}, {"at": [0, 1], "force": 0.5}]},
    },
    # Fixtures on a support (certificate-format.md section 7): a square part on four legs (+-1,+-1), each
    # carrying 1/4 with mu = 1/2 (friction discs of radius 1/8), against a frictionless pin at (-1,0) pushing
    # along +x (generator (1,0,0)), under three loads; and the four-legged table with the same pin, every leg
    # force unknown, under three more.
    "fixture_pin_push": dict(FIXTURE, name="part on four legs and a pin, pushed by (-1, 1/4) at (1,0): held", load={"force": [-1, "1/4"], "at": [1, 0]}),
    "fixture_pin_lift": dict(FIXTURE, name="part on four legs and a pin, pushed by (0, 1) at (1,0): it turns about "
                             "the pin", load={"force": [0, 1], "at": [1, 0]}),
    "fixture_pin_pull": dict(FIXTURE, name="part on four legs and a pin, pulled by (1/2, 0) at the centre: friction "
                             "just holds it", load={"force": ["1/2", 0], "at": [0, 0]}),
    "table_pinned_nudged": dict(TABLE_PINNED, name="four-legged table with a pin at (-1,0), every leg force "
                                "unknown, load (1/2, 0, 0): held by every distribution", load={"wrench": ["1/2", 0, 0]}),
    "table_pinned_shoved": dict(TABLE_PINNED, name="the pinned table under (3/2, 0, 0): moves under every "
                                "distribution", load={"wrench": ["3/2", 0, 0]}),
    "table_pinned_pushed": dict(TABLE_PINNED, name="the pinned table under (1/2, 1/2, 9/10): depends on the "
                                "distribution", load={"wrench": ["1/2", "1/2", "9/10"]}),
    # Support regions (certificate-format.md section 6.4): a uniform square, and a square frame (a hole).
    "square_region": {
        "wrenchkit": 1,
        "name": "uniform square [-1,1]^2, W = 1, mu = 1 (theory-sliding.md 6: h(0,0,1) = (sqrt 2 + asinh 1)/3)",
        "support": {"mu": 1, "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform",
                                          "force": 1}]},
    },
    # Hold over a region (section 7.4): the uniform square [-1,1]^2 (W = 1, mu = 1) under the pinned part.
    "square_region_pin_push": {"wrenchkit": 1, "name": "part on a uniform square region, pin at (-1,0), pushed by "
                               "(-1, 0) at (0, 1/4): the pin and the region's friction hold it", "body": SQUARE_BODY,
                               "contacts": PIN, "support": {"mu": 1, "regions": [SQUARE_REGION]},
                               "load": {"force": [-1, 0], "at": [0, "1/4"]}},
    "square_region_pin_turn": {"wrenchkit": 1, "name": "the same part pushed by (-1, 0) at (0, 1): it turns about "
                               "the centre", "body": SQUARE_BODY, "contacts": PIN,
                               "support": {"mu": 1, "regions": [SQUARE_REGION]},
                               "load": {"force": [-1, 0], "at": [0, 1]}},
    # Hold over a region with legs whose forces are not given (section 7.5, format 2): the mat [-1/2,1/2]^2 (uniform,
    # force 1) and legs (-2,0), (0,0), (2,0) carrying W - 1 = 4 about the origin: F's vertices (0,4,0) and (2,0,2).
    "mat_legs_nudged": dict(MAT_LEGS, name="mat and three legs of unknown force, pushed by (9/4, 0) through the centre: "
                            "held by every distribution", load={"wrench": ["9/4", 0, 0]}),
    "mat_legs_shoved": dict(MAT_LEGS, name="mat and three legs of unknown force, pushed by (3, 0) through the centre: "
                            "moves under every distribution", load={"wrench": [3, 0, 0]}),
    "mat_legs_twisted": dict(MAT_LEGS, name="mat and three legs of unknown force, twisted by the moment 1: depends on "
                             "the distribution", load={"wrench": [0, 0, 1]}),
    # Stick / slide over the same support (section 6.5, format 2): the load is the certificate's.
    "mat_legs": dict(MAT_LEGS, name="mat [-1/2,1/2]^2 (uniform, force 1) and legs (-2,0), (0,0), (2,0) without forces, "
                     "W = 5 at the origin, mu = 1/2: F's vertices (0, 4, 0) and (2, 0, 2)"),
    "square_frame": {
        "wrenchkit": 1,
        "name": "the frame [-2,2]^2 minus [-1,1]^2, uniform, W = 1, mu = 1, written clockwise",
        "support": {"mu": 1, "regions": [{"outline": [[-2, 2], [2, 2], [2, -2], [-2, -2]],
                                          "holes": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]],
                                          "pressure": "uniform", "force": 1}]},
    },
    # Pushing (certificate-format.md section 8, format 6): the square [-1,1]^2 sliding on its support, pushed at
    # its bottom edge y = -1 (inward normal (0, 1)).
    "push_square": {"wrenchkit": 1, "name": "the square on four legs (force 1 each, mu = 1/2), pushed at (1/2, -1) with "
                    "mu = 1 along (1, 1): the edges vote apart, the velocity ccw", "body": SQUARE_OUTLINE,
                    "support": {"mu": "1/2", "points": [{"at": at, "force": 1} for at in CORNERS]},
                    "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]}},
    "push_slide": {"wrenchkit": 1, "name": "the square on four legs, pushed at (1/2, -1) with mu = 1/2 along (-1, 1): "
                   "its left edge through c, a translation, the contact sliding on the left edge",
                   "body": SQUARE_OUTLINE,
                   "support": {"mu": "1/2", "points": [{"at": at, "force": 1} for at in CORNERS]},
                   "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": "1/2", "velocity": [-1, 1]}},
    "push_slide_right": {"wrenchkit": 1, "name": "the square on four legs, pushed at (1/2, -1) with mu = 1/4 along (1, 1): "
                         "the contact slides on the right edge, the body slipping and turning ccw",
                         "body": SQUARE_OUTLINE,
                         "support": {"mu": "1/2", "points": [{"at": at, "force": 1} for at in CORNERS]},
                         "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [1, 1]}},
    "push_stick_pivot": {"wrenchkit": 1, "name": "three legs; the pusher at (1, -1) moving (1, 1) turns the body about the leg at (0, 0): a sticking pivot", "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [2, 0], "force": 1, "mu": 1}, {"at": [0, 2], "force": "1/8", "mu": 1}]}, "pusher": {"at": [1, -1], "normal": [0, 1], "mu": 1, "velocity": [1, 1]}},
    "push_slide_pivot": {"wrenchkit": 1, "name": "three legs pushed with mu = 1/5: the contact slides from the facet of the leg at (0, 0)", "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [2, 0], "force": 1, "mu": 1}, {"at": [0, 2], "force": "1/8", "mu": 1}]}, "pusher": {"at": [1, -1], "normal": [0, 1], "mu": "1/5", "velocity": [1, 1]}},
    "push_tangent_pivot": {"wrenchkit": 1, "name": "three legs pushed with mu = 1/10: the pushing forces end at the facet of the leg at (0, 0)", "support": {"points": [{"at": [0, 0], "force": 1, "mu": 1}, {"at": [1, 1], "force": "1/8", "mu": 1}, {"at": [-1, 1], "force": "1/8", "mu": 1}]}, "pusher": {"at": [0, -1], "normal": [0, 1], "mu": "1/10", "velocity": [1, 1]}},
    "push_pivot": {"wrenchkit": 1, "name": "three legs pushed at (10, -1) with mu = 1/5 along (-1, 2): the contact slides "
                   "on the right edge and the body turns about the leg at (8, 3), exactly",
                   "support": {"points": [{"at": [8, 3], "force": 7, "mu": "8/10"}, {"at": [5, 8], "force": 6, "mu": "1/10"},
                                          {"at": [-1, -4], "force": 4, "mu": "3/10"}]},
                   "pusher": {"at": [10, -1], "normal": [-4, 1], "mu": "2/10", "velocity": [-1, 2]}},
    "push_depends": {"wrenchkit": 1, "name": "the square on four points of different mu, forces not given (W = 4 at "
                     "the origin), pushed frictionless along x = -1/10: ccw under (2, 2, 0, 0), cw under (0, 0, 2, 2)",
                     "body": SQUARE_OUTLINE,
                     "support": {"weight": 4, "pressure_center": [0, 0],
                                 "points": [{"at": [-1, 0], "mu": 1}, {"at": [1, 0], "mu": "1/10"},
                                            {"at": [0, 1], "mu": "1/2"}, {"at": [0, -1], "mu": "1/2"}]},
                     "pusher": {"at": ["-1/10", -1], "normal": [0, 1], "velocity": [0, 1]}},
    "push_square_unknown": {"wrenchkit": 1, "name": "the square on four legs of unknown force (W = 4 at the origin, "
                            "mu = 1/2), pushed at (1/2, -1) with mu = 1/4 along y: both edges vote ccw",
                            "body": SQUARE_OUTLINE,
                            "support": {"mu": "1/2", "weight": 4, "pressure_center": [0, 0],
                                        "points": [{"at": at} for at in CORNERS]},
                            "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [0, 1]}},
    "push_contact_depends": {"wrenchkit": 1, "name": "the square on four legs and a fifth at (0, 1/2), forces not given "
                             "(W = 4 at the origin, mu = 1/2), pushed at (1/2, -1) with mu = 1/4 along y: the contact "
                             "slides under some distributions and sticks under others",
                             "body": SQUARE_OUTLINE,
                             "support": {"mu": "1/2", "weight": 4, "pressure_center": [0, 0],
                                         "points": [{"at": at} for at in CORNERS] + [{"at": [0, "1/2"]}]},
                             "pusher": {"at": ["1/2", -1], "normal": [0, 1], "mu": "1/4", "velocity": [0, 1]}},
    "push_square_centre": {"wrenchkit": 1, "name": "the square on four legs pushed frictionless at (0, -1) along "
                           "(1, 1): both edges pass through the centre of friction, the body translates",
                           "body": SQUARE_OUTLINE,
                           "support": {"mu": "1/2", "points": [{"at": at, "force": 1} for at in CORNERS]},
                           "pusher": {"at": [0, -1], "normal": [0, 1], "velocity": [1, 1]}},
    # A line pusher (certificate-format.md section 8.3, PU-3): the square on four legs (force 1, mu 1/2, c = 0, R^2 = 2)
    # pushed along its bottom edge from (-1/2, -1) to (1/2, -1), mu 1/2 (cone edges (-1/2, 1), (1/2, 1)).
    "push_fence": dict(FENCE, name="the square pushed by a fence along its bottom edge, translating up: stable",
                       pusher=dict(FENCE_PUSHER, velocity=[0, 1])),
    "push_fence_slanted": dict(FENCE, name="the fence translating along (1, 1), beyond the right edge: unstable",
                               pusher=dict(FENCE_PUSHER, velocity=[1, 1])),
    "push_fence_turning": dict(FENCE, name="the fence turning ccw about (-10, -1): stable by PU-3's conditions",
                               pusher=dict(FENCE_PUSHER, velocity=[0, 1], omega="1/10")),
    "push_fence_near": dict(FENCE, name="the fence turning ccw about (-6, -1): stable, end 1 by the LP's dual",
                            pusher=dict(FENCE_PUSHER, velocity=[0, 1], omega="1/6")),
    "push_fence_close": dict(FENCE, name="the fence turning ccw about (-2, -1): unstable, two legs lean past the left edge",
                             pusher=dict(FENCE_PUSHER, velocity=[0, 1], omega="1/2")),
    "push_fence_aside": dict(FENCE, name="a frictionless fence at the square's right, from (1/2, -1) to (1, -1), translating up: "
                             "unstable, but every force it can apply turns the body ccw",
                             pusher={"segment": [["1/2", -1], [1, -1]], "normal": [0, 1], "mu": 0, "velocity": [0, 1]}),
    "push_barbell": {"wrenchkit": 1, "name": "the square on two legs (-1, 0), (1, 0) pushed frictionless at (0, -1): "
                     "the friction lies on one line through c, so the votes do not decide", "body": SQUARE_OUTLINE,
                     "support": {"mu": "1/2", "points": [{"at": [-1, 0], "force": 1}, {"at": [1, 0], "force": 1}]},
                     "pusher": {"at": [0, -1], "normal": [0, 1], "velocity": [1, 1]}},
}

# ----------------------------------------------------------------------------------------------
# Certificates: (scene, description, expected, certificate)
# expected: "valid", or "invalid:<reason>|<text>" where <reason> is what verify() below returns and
# <text> is a substring of the C++ checker's message (the test suite checks it).
# certificate None: computed by computed() below, which may also give `expected` when that is None.


def comb(*terms):
    return [{"contact": c, "edge": e, "weight": w} for c, e, w in terms]


def refs(*pairs):
    return [{"contact": c, "edge": e} for c, e in pairs]


def positive(prop, combination, independent):
    return {"wrenchkit_certificate": 1, "property": prop, "holds": True,
            "combination": combination, "independent": independent}


def equilibrium_true(combination):
    return {"wrenchkit_certificate": 1, "property": "equilibrium", "holds": True, "combination": combination}


def negative(prop, twist, reading=None):
    cert = {"wrenchkit_certificate": 1, "property": prop, "holds": False, "twist": twist}
    if reading is not None:
        cert["reading"] = reading
    return cert


def motion(claim, load, **rest):
    """A sliding certificate (certificate-format.md section 6): load p = (fx, fy, m) as rationals."""
    return dict({"wrenchkit_certificate": 1, "property": "motion", "load": [str(F(v)) for v in load],
                 "motion": claim}, **rest)


def hold(claim, **rest):
    return dict({"wrenchkit_certificate": 1, "property": "hold", "holds": claim}, **rest)


def hold2(claim, **rest):
    """A hold certificate in format 2 (section 7.5: regions together with forces not given)."""
    return dict({"wrenchkit_certificate": 2, "property": "hold", "holds": claim}, **rest)


def motion2(claim, load, **rest):
    """A sliding certificate in format 2 (section 6.5: regions together with forces not given)."""
    return dict(motion(claim, load, **rest), wrenchkit_certificate=2)


def motion3(claim, load, **rest):
    """A sliding certificate in format 3 (section 6.6: the boundary is "impending"; "slides" is strict)."""
    return dict(motion(claim, load, **rest), wrenchkit_certificate=3)


def hold3(claim, **rest):
    """A hold certificate in format 3 (section 7.6: true is held with margin, the boundary is "impending")."""
    return dict(hold(claim, **rest), wrenchkit_certificate=3)


def hold_witness(distribution, combination, forces):
    return {"distribution": distribution, "combination": combination, "support_forces": forces}


def stick_witness(distribution, forces):
    return {"distribution": distribution, "support_forces": forces}


def slide_witness(distribution, twist, speeds):
    return {"distribution": distribution, "twist": twist, "speed_bounds": speeds}


def block(cells, **rest):
    """A region's block (certificate-format.md section 6.4): cells = (vertices, triangles) and forces or speed_bounds."""
    vertices, triangles = cells
    return dict({"vertices": [[str(F(x)), str(F(y))] for x, y in vertices], "triangles": triangles}, **rest)


# The uniform square [-1,1]^2 (W = 1, mu = 1): two cells along the diagonal (pressure centroids (1/3, -1/3) and
# (-1/3, 1/3), F = 1/2 each), carrying (1/2, 0, 1/4) with forces (7/16, 3/16) and (1/16, -3/16), strictly inside
# their discs of radius 1/2; four cells around the centre, whose corner speeds for q = (0, 0, 1) are 0 and
# sqrt 2 <= 17/12, bound the power (sqrt 2 + asinh 1)/3 ~ 0.765 by 4 (2 * 17/12)/12 = 17/18 <= 1 = q.p for (0, 0, 1).
SQUARE_2 = ([[-1, -1], [1, -1], [1, 1], [-1, 1]], [[0, 1, 2], [0, 2, 3]])
MAT_2 = ([["-1/2", "-1/2"], ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]], [[0, 1, 2], [0, 2, 3]])
MAT_4 = ([[0, 0], ["-1/2", "-1/2"], ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]], [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]])
MAT_PUSH = block(MAT_2, forces=[["-1/8", "0"], ["-1/8", "0"]])
MAT_SLIDE_X = block(MAT_2, speed_bounds=["1", "1", "1", "1"])
MAT_HOLDING = dict(hold_witness(["2", "0", "2"], [], [["0", "1/4"], ["0", "0"], ["0", "-1/4"]]),
                   regions=[block(MAT_2, forces=[["0", "0"], ["0", "0"]])])
MAT_FAILING = dict(slide_witness(["0", "4", "0"], ["0", "0", "1"], ["2", "0", "2"]),
                   regions=[block(MAT_4, speed_bounds=["0", "17/24", "17/24", "17/24", "17/24"])])
# Motion over the mat and legs (section 6.5). (2, 0, 0) sticks at both vertices: the middle leg (7/4, 0) (disc 2) or the
# outer legs (7/8, 0) each (discs 1), and the mat's two cells (1/8, 0) each (discs 1/4; their moments cancel).
MAT_STICK_X = block(MAT_2, forces=[["1/8", "0"], ["1/8", "0"]])
MAT_STICKS = [dict(stick_witness(["0", "4", "0"], [["0", "0"], ["7/4", "0"], ["0", "0"]]), regions=[MAT_STICK_X]),
              dict(stick_witness(["2", "0", "2"], [["7/8", "0"], ["0", "0"], ["7/8", "0"]]), regions=[MAT_STICK_X])]
# (0, 0, 1) sticks with (2, 0, 2): (0, -1/4) at (-2, 0) and (0, 1/4) at (2, 0) give the moment 1; slides with (0, 4, 0)
# under the rotation about the middle leg (the mat resists at most 17/72).
MAT_STICKING = dict(stick_witness(["2", "0", "2"], [["0", "-1/4"], ["0", "0"], ["0", "1/4"]]),
                    regions=[block(MAT_2, forces=[["0", "0"], ["0", "0"]])])
SQUARE_4 = ([[0, 0], [-1, -1], [1, -1], [1, 1], [-1, 1]], [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]])
SQUARE_STICKS = motion("sticks", [F(1, 2), 0, F(1, 4)], support_forces=[],
                       regions=[block(SQUARE_2, forces=[["7/16", "3/16"], ["1/16", "-3/16"]])])
SQUARE_SLIDES = motion("slides", [0, 0, 1], twist=["0", "0", "1"], speed_bounds=[],
                       regions=[block(SQUARE_4, speed_bounds=["0", "17/12", "17/12", "17/12", "17/12"])])
# Hanging vertices: the cell (0,0),(1,1),(-1,1) cut at the midpoint (1/2, 1/2) of an edge its neighbour keeps whole,
# and the cell (0,0),(-1,-1),(1,-1) cut at (0,-1), the middle of the region's bottom edge.
SQUARE_SLIDES_HANGING = motion(
    "slides", [0, 0, 1], twist=["0", "0", "1"], speed_bounds=[],
    regions=[block(([[0, 0], [-1, -1], [1, -1], [1, 1], [-1, 1], ["1/2", "1/2"], [0, -1]],
                    [[0, 1, 6], [0, 6, 2], [0, 2, 3], [0, 5, 4], [5, 3, 4], [0, 4, 1]]),
                   speed_bounds=["0", "17/12", "17/12", "17/12", "17/12", "17/24", "1"])])
# The frame [-2,2]^2 minus [-1,1]^2 (area 12, W = 1): eight cells, two per side. It carries (1/4, 0, 0) with the
# force (1/32, 0) on each cell; the translation (1, 0, 0) moves every point with speed 1, so its power is
# W = 1 exactly and the load (1, 0, 0) is on the limit surface: it slides (u = 1, bound 1 = q.p).
FRAME_CELLS = ([[-2, -2], [2, -2], [2, 2], [-2, 2], [-1, -1], [1, -1], [1, 1], [-1, 1]],
               [[0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
FRAME_STICKS = motion("sticks", [F(1, 4), 0, 0], support_forces=[],
                      regions=[block(FRAME_CELLS, forces=[["1/32", "0"]] * 8)])
FRAME_SLIDES = motion("slides", [1, 0, 0], twist=["1", "0", "0"], speed_bounds=[],
                      regions=[block(FRAME_CELLS, speed_bounds=["1"] * 8)])


# The table (legs (1,1), (-1,1), (-1,-1), (1,-1), mu = W = 1, c = 0): F's vertices are the two diagonal
# barbells (1/2, 0, 1/2, 0) and (0, 1/2, 0, 1/2).
TABLE_STICKS = motion("sticks", [F(1, 2), 0, 0], vertices=[  # g = (1/4, 0), strictly inside |g| < 1/2, at both legs of the diagonal
    stick_witness(["1/2", "0", "1/2", "0"], [["1/4", "0"], ["0", "0"], ["1/4", "0"], ["0", "0"]]),
    stick_witness(["0", "1/2", "0", "1/2"], [["0", "0"], ["1/4", "0"], ["0", "0"], ["1/4", "0"]])])
# q = (1, 0, 0): every speed is 1; mu_i u_i = 1 <= y0 = 1, so the frictional power is at most W = 1 < 3/2.
TABLE_SLIDES = motion("slides", [F(3, 2), 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"],
                      dual=["1", "0", "0"])
# (1/2, 1/2, 9/10): on the diagonal (1,1)-(-1,-1) it sticks with g = (1/40, 19/40) and (19/40, 1/40) (sum
# (1/2, 1/2), moment 9/10, |g|^2 = 181/800 < 1/4); on the other it slides: q = (1, 1, 1) has speeds
# 2, 0, 2, 2 sqrt 2 <= 17/6, and power 19/10 > (1/2) 17/6 = 17/12 (found by a small exact search over integer twists).
TABLE_DEPENDS = motion("depends", [F(1, 2), F(1, 2), F(9, 10)],
                       sticking=stick_witness(["1/2", "0", "1/2", "0"],
                                              [["1/40", "19/40"], ["0", "0"], ["19/40", "1/40"], ["0", "0"]]),
                       sliding=slide_witness(["0", "1/2", "0", "1/2"], ["1", "1", "1"], ["2", "0", "2", "17/6"]))


SQUARE = comb((0, "normal", "1"), (1, "normal", "1"), (2, "normal", "1"), (3, "normal", "1"))
SQUARE_IND = refs((0, "normal"), (1, "normal"), (2, "normal"))
TWO_FINGER = comb((0, "left", "1"), (0, "right", "1"), (1, "left", "1"), (1, "right", "1"))
TWO_FINGER_IND = refs((0, "left"), (0, "right"), (1, "left"))
TRIANGLE_EDGES = [(c, e) for c in range(3) for e in ("left", "right")]
WRENCHES = comb((0, "wrench", "1"), (1, "wrench", "1"), (2, "wrench", "1"), (3, "wrench", "1"))
WRENCHES_IND = refs((0, "wrench"), (1, "wrench"), (2, "wrench"))

def quality(norm, normalize, epsilon, **rest):
    cert = {"wrenchkit_certificate": 4, "property": "quality", "norm": norm, "normalize": normalize,
            "torque_scale": "1", "about": ["0", "0"], "epsilon": epsilon}
    cert.update(rest)
    return cert


# Two fingers with mu = 1 (section 3.4): the generators (1,1,-1), (1,-1,1), (-1,-1,-1), (-1,1,1) are a regular
# tetrahedron whose faces are at distance 1/sqrt 3 (L1); the L-infinity space's nearest facet has normal (-2, 1, -1)
# and support 2, distance sqrt(2/3). Unit-force divides every edge by sqrt 2: the scale 181/256 is within 1/256 of
# 1/sqrt 2, each edge has length sqrt 3 <= 7/4, so epsilon is within 7/1024 of (181/256)/sqrt 3.
EXACT = [{"scale": "1", "error": "0", "bound": "7/4"}] * 2
TETRA = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
ROOT2 = [{"scale": "181/256", "error": "1/256", "bound": "7/4"}] * 2

# Critical friction (section 3.5), as the engine writes it: two fingers whose contact line makes tan 1/2 with both
# normals (mu* = 1/2: not closed at 1/2, closed at 2/3, no minor changing sign between); the ladder of theory.md
# section 9 under its weight (balanced at 1/7, not at 1/10, nothing changing between); two fingers pushing the same
# way (never: the translation (1, 0) is orthogonal to every tangent wrench).
CRIT_OFFSET = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "force_closure", "critical_mu": {"lower": "1/2", "upper": "1/2"}, "below": {"mu": "1/2", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, "twist": ["0", "1", "1"], "reading": {"label": "+", "point": ["-1", "0"]}}}, "above": {"mu": "2/3", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": true, "combination": [{"contact": 0, "edge": "left", "weight": "7"}, {"contact": 0, "edge": "right", "weight": "1"}, {"contact": 1, "edge": "left", "weight": "7"}, {"contact": 1, "edge": "right", "weight": "1"}], "independent": [{"contact": 0, "edge": "left"}, {"contact": 0, "edge": "right"}, {"contact": 1, "edge": "left"}]}}, "constant": true}''')
CRIT_LADDER_CLOSURE = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "force_closure", "critical_mu": {"lower": "4/3", "upper": "4/3"}, "below": {"mu": "4/3", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, "twist": ["3", "4", "1"], "reading": {"label": "+", "point": ["-4", "3"]}}}, "above": {"mu": "2", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": true, "combination": [{"contact": 0, "edge": "left", "weight": "10"}, {"contact": 0, "edge": "right", "weight": "2"}, {"contact": 1, "edge": "left", "weight": "5"}, {"contact": 1, "edge": "right", "weight": "11"}], "independent": [{"contact": 0, "edge": "left"}, {"contact": 0, "edge": "right"}, {"contact": 1, "edge": "left"}]}}, "constant": true}''')
CRIT_LADDER = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "equilibrium", "critical_mu": {"lower": "1/7", "upper": "1/7"}, "below": {"mu": "1/10", "certificate": {"wrenchkit_certificate": 1, "property": "equilibrium", "holds": false, "twist": ["340", "34", "101"], "reading": {"label": "+", "point": ["-34/101", "340/101"]}}}, "above": {"mu": "1/7", "certificate": {"wrenchkit_certificate": 1, "property": "equilibrium", "holds": true, "combination": [{"contact": 0, "edge": "left", "weight": "49/50"}, {"contact": 1, "edge": "left", "weight": "7/50"}]}}, "constant": true}''')
CRIT_MOMENT = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "equilibrium", "critical_mu": {"lower": "1/2", "upper": "1/2"}, "below": {"mu": "1/2", "certificate": {"wrenchkit_certificate": 1, "property": "equilibrium", "holds": false, "twist": ["0", "1", "1"], "reading": {"label": "+", "point": ["-1", "0"]}}}, "above": {"mu": "2/3", "certificate": {"wrenchkit_certificate": 1, "property": "equilibrium", "holds": true, "combination": [{"contact": 0, "edge": "left", "weight": "3"}, {"contact": 1, "edge": "left", "weight": "3"}]}}, "constant": true}''')
CRIT_MARGIN = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "force_closure", "scaling": "proportional", "critical_mu": {"lower": "2/3", "upper": "2/3"}, "below": {"mu": "2/3", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, "twist": ["0", "1", "1"], "reading": {"label": "+", "point": ["-1", "0"]}}}, "above": {"mu": "1", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": true, "combination": [{"contact": 0, "edge": "left", "weight": "9"}, {"contact": 0, "edge": "right", "weight": "3"}, {"contact": 1, "edge": "left", "weight": "10"}, {"contact": 1, "edge": "right", "weight": "2"}], "independent": [{"contact": 0, "edge": "left"}, {"contact": 0, "edge": "right"}, {"contact": 1, "edge": "left"}]}}, "constant": true}''')
GRASPIT_SQUARE = json.loads(r'''{"wrenchkit_certificate": 4, "property": "quality", "norm": "L1", "normalize": "unit-normal", "torque_scale": "189812531/268435456", "torque_radius_squared": "2", "torque_scale_error": "1/268435456", "about": ["0", "0"], "epsilon": {"lower": "12148001919/171798691840", "upper": "12148002049/171798691840"}, "scales": [{"scale": "1", "error": "0", "bound": "17/16", "moment_bound": "13/128"}, {"scale": "1", "error": "0", "bound": "17/16", "moment_bound": "13/128"}, {"scale": "1", "error": "0", "bound": "17/16", "moment_bound": "13/128"}, {"scale": "1", "error": "0", "bound": "17/16", "moment_bound": "13/128"}], "boundary": [[0, 1, 4], [2, 0, 4], [1, 3, 5], [4, 1, 5], [3, 2, 5], [2, 4, 5], [0, 2, 6], [2, 3, 6], [3, 1, 7], [6, 3, 7], [1, 0, 7], [0, 6, 7]], "nearest": [2, 0, 4]}''')
CRIT_CHIROTOPE = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "force_closure", "critical_mu": {"lower": "7/2", "upper": "7/2"}, "below": {"mu": "7/2", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": false, "twist": ["-3", "4", "1"], "reading": {"label": "+", "point": ["-4", "-3"]}}}, "above": {"mu": "4", "certificate": {"wrenchkit_certificate": 1, "property": "force_closure", "holds": true, "combination": [{"contact": 0, "edge": "left", "weight": "116"}, {"contact": 0, "edge": "right", "weight": "460"}, {"contact": 1, "edge": "left", "weight": "615"}, {"contact": 1, "edge": "right", "weight": "41"}], "independent": [{"contact": 0, "edge": "left"}, {"contact": 0, "edge": "right"}, {"contact": 1, "edge": "left"}]}}, "constant": true}''')
CRIT_NEVER = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "force_closure", "critical_mu": "never", "limit_twist": ["1", "0", "0"]}''')
CRIT_NEVER_LOAD = json.loads(r'''{"wrenchkit_certificate": 4, "property": "critical_mu", "of": "equilibrium", "critical_mu": "never", "limit_twist": ["1", "0", "0"]}''')


# grasp regions (§3.6): the unit square's opposite sides close for |1 - s - t| < 1/2 with mu = 1/2
SQ_REGION = [["1/2", "0"], ["1", "0"], ["1", "1/2"], ["1/2", "1"], ["0", "1"], ["0", "1/2"]]


def regions_cert(pairs, mu="1/2", **rest):
    return dict({"wrenchkit_certificate": 5, "property": "grasp_regions", "fingers": 2, "mu": mu}, **rest, pairs=pairs)


SQ_PAIRS = [{"edges": [i, j], "closed": [SQ_REGION] if (i, j) in ((0, 2), (1, 3)) else []}
            for i in range(4) for j in range(i + 1, 4)]


# Pushing (section 8), as `wrenchkit push --certificate` writes them. push_square: D = 4 (1/2) = 2; the lines through
# (1/2, -1) along (-1, 1), (1, 1), (1, 1) have N = (1/2) (4p - sum r_i) x d = (1, -2) x d: -1, 3, 3 (c = 0).
PUSH_SQUARE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2"}, "votes": [{"lower": "-1", "upper": "-1"}, {"lower": "3", "upper": "3"}, {"lower": "3", "upper": "3"}], "center": ["0", "0"]}''')
# The contact mode (section 8.2, `push --contact`): push_square sticks, its rotation rate bracketed near 0.53605;
# push_slide slides on the left edge (the sticking force is beyond it, and the left edge is among the pushing forces).
PUSH_SQUARE_CONTACT = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2"}, "votes": [{"lower": "-1", "upper": "-1"}, {"lower": "3", "upper": "3"}, {"lower": "3", "upper": "3"}], "center": ["0", "0"], "contact": {"mode": "sticks", "bits": 64, "omega": ["147348867227/274877906944", "589395468909/1099511627776"]}}''')
PUSH_SLIDE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "none", "friction": {"lower": "2"}, "votes": [{"lower": "0", "upper": "0"}, {"lower": "2", "upper": "2"}, {"lower": "-1", "upper": "-1"}], "center": ["0", "0"], "contact": {"mode": "slides left", "bits": 64, "omega": ["-1/4", "-1/8"], "tangent_omega": ["-1/2", "0"], "sliding": {"slip": ["-1/2", "-1/2"], "slip_omega": [["0", "0"], ["0", "0"]], "omega": ["0", "0"]}}}''')
# push_stick_pivot: the pusher's velocity (1, 1) is perpendicular to the line to the leg (0, 0): the sticking motion is
# the rotation about it at rate 1 (PU-2 section 7), its facet holding the force (9/16, 27/16) inside the cone.
PUSH_STICK_PIVOT = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "17/8"}, "votes": [{"lower": "-9/4", "upper": "-9/4"}, {"lower": "5/2", "upper": "5/2"}, {"lower": "5/2", "upper": "5/2"}], "center": ["16/17", "2/17"], "contact": {"mode": "sticks", "bits": 64, "omega": ["1", "1"], "pivot": 0, "force": ["9/16", "27/16"]}}''')
# push_slide_pivot: push_stick_pivot with mu = 1/5 — the sticking motion is still the rotation about the leg (0, 0), but
# every force of its facet through the pusher is beyond the right edge (PU-2 section 8): it slides right.
PUSH_SLIDE_PIVOT = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "17/8"}, "votes": [{"lower": "-7/20", "upper": "-7/20"}, {"lower": "3/5", "upper": "3/5"}, {"lower": "5/2", "upper": "5/2"}], "center": ["16/17", "2/17"], "contact": {"mode": "slides right", "bits": 64, "omega": ["1", "1"], "pivot": 0, "tangent_omega": ["-996269925400733/2251799813685248", "-996269925399607/2251799813685248"], "sliding": {"slip": ["2458624365699259/144115188075855872", "2458624365771317/144115188075855872"], "slip_omega": [["2164414849554211/2251799813685248", "4328829699108491/4503599627370496"], ["4328829699103783/4503599627370496", "4328829699103921/4503599627370496"]], "omega": ["6926127518550805222292325169/7205759403792793600000000000", "6926127518588833177707674831/7205759403792793600000000000"]}}}''')
# push_tangent_pivot: the tangent (-1, 0) is perpendicular to the line to the leg (0, 0), and that rotation's facet is the
# end F(t) of the pushing forces (PU-2 section 8): the right edge is in their half-plane for every force of its chord.
PUSH_TANGENT_PIVOT = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "5/4"}, "votes": [{"lower": "-3/20", "upper": "-3/20"}, {"lower": "3/20", "upper": "3/20"}, {"lower": "3/2", "upper": "3/2"}], "center": ["0", "1/5"], "contact": {"mode": "slides right", "bits": 64, "omega": ["194822285446309/281474976710656", "779289141785799/1125899906842624"], "tangent_omega": ["-1", "-1"], "tangent_pivot": 0, "sliding": {"slip": ["8141328147255443/36028797018963968", "8141328147273457/36028797018963968"], "slip_omega": [["2475812579096303/4503599627370496", "2475812579096521/4503599627370496"], ["1237906289547423/2251799813685248", "309476572386883/562949953421312"]], "omega": ["39613001265494680775214438137/72057594037927936000000000000", "39613001265567191224785561863/72057594037927936000000000000"]}}}''')
# push_pivot: the sliding motion is the rotation about the leg (8, 3) (PU-2 section 6): slip 5/7 along (-1, -4), rate -3/7.
PUSH_PIVOT = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "cw", "friction": {"lower": "37/5"}, "votes": [{"lower": "-2404/25", "upper": "-2404/25"}, {"lower": "-1066/25", "upper": "-1066/25"}, {"lower": "153/5", "upper": "153/5"}], "center": ["233/37", "84/37"], "contact": {"mode": "slides right", "bits": 64, "omega": ["5309636483810193/36028797018963968", "5309636483828207/36028797018963968"], "tangent_omega": ["-3479513353260505/9007199254740992", "-3479513353256001/9007199254740992"], "sliding": {"pivot": 0, "slip": ["5/7", "5/7"], "omega": ["-3/7", "-3/7"]}}}''')
# push_slide_right (--tolerance 1e-6): slides on the right edge; the body's velocity at p is (1, 1) + x (-1, 0) with x in
# the slip bracket, its rate in "omega" for every x there (PU-2 section 5).
PUSH_SLIDE_RIGHT = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2"}, "votes": [{"lower": "1/2", "upper": "1/2"}, {"lower": "3/2", "upper": "3/2"}, {"lower": "3", "upper": "3"}], "center": ["0", "0"], "contact": {"mode": "slides right", "bits": 64, "omega": ["17/32", "9/16"], "tangent_omega": ["-1/2", "0"], "sliding": {"slip": ["5737404238460715/18014398509481984", "5737413245659969/18014398509481984"], "slip_omega": [["3834844099614311/9007199254740992", "3834844106035333/9007199254740992"], ["7669685342738903/18014398509481984", "7669685355580945/18014398509481984"]], "omega": ["122714909175396279708447/288230376151711744000000", "122715067701556824291553/288230376151711744000000"]}}}''')
# push_depends: every line is x = -1/10 upward; D = 2 + f0/10 >= 2 over F (f0 = f1, f2 + f3 = 4 - 2 f0).
PUSH_DEPENDS = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "depends", "friction": {"lower": "2", "dual_lower": ["-1/2", "2/5", "0"]}, "turns": {"ccw": ["2", "2", "0", "0"], "cw": ["0", "0", "2", "2"]}}''')
# push_square_unknown: one coefficient, so c = (0, 0) for every f in F and each vote is constant over F (its duals
# prove both bounds): N = (1/2) (4p - W c) x d = (1, -2) x d for d = (-1/4, 1), (1/4, 1), (0, 1): 1/2, 3/2, 1.
PUSH_UNKNOWN = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2", "dual_lower": ["-1/2", "0", "0"]}, "votes": [{"lower": "1/2", "dual_lower": ["-1/8", "1/2", "1/8"], "upper": "1/2", "dual_upper": ["1/8", "-1/2", "-1/8"]}, {"lower": "3/2", "dual_lower": ["-3/8", "1/2", "-1/8"], "upper": "3/2", "dual_upper": ["3/8", "-1/2", "1/8"]}, {"lower": "1", "dual_lower": ["-1/4", "1/2", "0"], "upper": "1", "dual_upper": ["1/4", "-1/2", "0"]}], "center": ["0", "0"]}''')
# push_square_centre: both edges along (0, 1) through c = 0 (votes 0), the velocity ccw: "none"; the legs' friction is
# off the line through c perpendicular to pc (the x-axis), so the tie is decided.
PUSH_CENTRE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "none", "friction": {"lower": "2"}, "votes": [{"lower": "0", "upper": "0"}, {"lower": "0", "upper": "0"}, {"lower": "2", "upper": "2"}], "center": ["0", "0"]}''')


# Line pushers (section 8.3), as `wrenchkit push --certificate` writes them. push_fence: the load (0, 1) through c
# inside CF; push_fence_slanted: e- x v = 1/2 - 1 < 0; push_fence_turning: q = (-10, -1) passes the direction facets,
# the bisector of end 0 and end 1's corrected tip line (4 >= 2 + E, E ~ 0.037); push_fence_near: q = (-6, -1) fails the
# tip line (2 < 2 + E ~ 2.11) but the LP's dual over the legs proves end 1; push_fence_close: q = (-2, -1), weights 1
# and 1 at (-1, 1) and (1, -1) lean past the left edge (2/sqrt(5) - 1/2 > 0).
FENCE_STABLE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "none", "center": ["0", "0"], "stable": {"verdict": "stable", "R2": "2"}}''')
FENCE_SLANTED = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "center": ["0", "0"], "stable": {"verdict": "unstable", "R2": "2", "facet": "right edge"}}''')
FENCE_TURNING = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "center": ["0", "0"], "stable": {"verdict": "stable", "R2": "2", "R_hi": "283/200", "d_lo": "10049/1000", "alpha_hi": "1119/1000"}}''')
# push_fence_turning with --region: each sense's tip line (c - e_t).(q - c) >= T, T = 2.909923 >= 2 + E(T/alpha_hi)
# (E ~ 0.9099 at d ~ 2.603: the fixed point, rounded up), and the stable translations: the friction cone itself.
FENCE_REGION = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "center": ["0", "0"], "stable": {"verdict": "stable", "R2": "2", "R_hi": "283/200", "d_lo": "10049/1000", "alpha_hi": "1119/1000"}, "region": {"R_hi": "707107/500000", "ccw": {"alpha_hi": "559017/500000", "T": "2909923/1000000"}, "cw": {"alpha_hi": "559017/500000", "T": "2909923/1000000"}, "translations": [["1/2", "1"], ["-1/2", "1"]]}}''')
# push_fence_aside: the line x = 0 through c along v misses the segment (end 0's facet), and every corner (e_k - c) x (0, 1)
# is positive (1/2 and 1): the body turns ccw (PU-1's first lemma) though it leaves the pusher.
FENCE_ASIDE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "center": ["0", "0"], "stable": {"verdict": "unstable", "R2": "2", "facet": "end 0"}}''')
FENCE_NEAR = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "center": ["0", "0"], "stable": {"verdict": "stable", "R2": "2", "duals": {"end 1": ["-37483/1000000", "210017/250000", "132551/500000"]}, "bits": 64}}''')
FENCE_CLOSE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "center": ["0", "0"], "stable": {"verdict": "unstable", "R2": "2", "facet": "left edge", "witness": {"points": [["-1", "1"], ["1", "-1"]], "weights": ["1", "1"], "bits": 64}}}''')


# The rotation centres (section 8.4, `push --locus`, PU-4). push_square: ccw only (the votes); on the sticking line
# x + y = -1/2 the bisector (1, -2).q <= 5/4 stops at (1/12, -7/12) and the tip line -x/2 + y <= T (T = 2.909923, the
# fixed point of PU-3 section 6 at alpha = |c - p| = sqrt(5)/2) at x = -(2/3)(T + 1/2); the slides' pieces add the
# load along an edge (the legs' extent) and the slip's side of the line through p across v. push_square_unknown: the
# same bounds over every distribution of the unknown legs (c the centre of pressure). push_slide: "none", no centre.
# The contact mode over forces not given (section 8.2, "depends"): push_contact_depends — under the legs (2, 0, 2, 0, 0)
# (the diagonal through (-1, -1) and (1, 1)) the contact slides left, under (0, 2, 0, 2, 0) it sticks, each certified
# as PU-2 does for given forces, and both distributions are in F (weight 4, pressure centre 0).
CONTACT_DEPENDS = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2", "dual_lower": ["-1/2", "0", "0"]}, "votes": [{"lower": "1/2", "dual_lower": ["-1/8", "1/2", "1/8"], "upper": "1/2", "dual_upper": ["1/8", "-1/2", "-1/8"]}, {"lower": "3/2", "dual_lower": ["-3/8", "1/2", "-1/8"], "upper": "3/2", "dual_upper": ["3/8", "-1/2", "1/8"]}, {"lower": "1", "dual_lower": ["-1/4", "1/2", "0"], "upper": "1", "dual_upper": ["1/4", "-1/2", "0"]}], "center": ["0", "0"], "contact": {"mode": "depends", "witnesses": [{"forces": ["2", "0", "2", "0", "0"], "mode": "slides left", "bits": 64, "omega": ["1718065340023205/4503599627370496", "1718065340025457/4503599627370496"], "tangent_omega": ["-3791913694410813/9007199254740992", "-3791913694406309/9007199254740992"], "sliding": {"slip": ["-4486075893447883/144115188075855872", "-4486075893375825/144115188075855872"], "slip_omega": [["7149683455126491/18014398509481984", "7149683455127277/18014398509481984"], ["7149683455123011/18014398509481984", "7149683455123797/18014398509481984"]], "omega": ["7149683455110553168983800199/18014398509481984000000000000", "7149683455139734831016199801/18014398509481984000000000000"]}}, {"forces": ["0", "2", "0", "2", "0"], "mode": "sticks", "bits": 64, "omega": ["6293520118068495/36028797018963968", "6293520118086509/36028797018963968"]}]}}''')
LOCUS_SQUARE = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2"}, "votes": [{"lower": "-1", "upper": "-1"}, {"lower": "3", "upper": "3"}, {"lower": "3", "upper": "3"}], "center": ["0", "0"], "locus": {"R_hi": "707107/500000", "alpha_hi": "559017/500000", "T": "2909923/1000000", "ccw": [{"mode": "sticks", "bounded": true, "polygon": [["-1136641/500000", "886641/500000"], ["1/12", "-7/12"]]}, {"mode": "slides left", "bounded": true, "polygon": [["-5/4", "3/4"], ["1/12", "-7/12"], ["1/2", "-3/8"], ["1/2", "5/2"]]}, {"mode": "slides right", "bounded": true, "polygon": [["-1636641/500000", "636641/500000"], ["-11/12", "-13/12"], ["1/12", "-7/12"], ["-1136641/500000", "886641/500000"]]}], "cw": null, "arm_hi": "1886641/500000"}}''')
LOCUS_UNKNOWN = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2", "dual_lower": ["-1/2", "0", "0"]}, "votes": [{"lower": "1/2", "dual_lower": ["-1/8", "1/2", "1/8"], "upper": "1/2", "dual_upper": ["1/8", "-1/2", "-1/8"]}, {"lower": "3/2", "dual_lower": ["-3/8", "1/2", "-1/8"], "upper": "3/2", "dual_upper": ["3/8", "-1/2", "1/8"]}, {"lower": "1", "dual_lower": ["-1/4", "1/2", "0"], "upper": "1", "dual_upper": ["1/4", "-1/2", "0"]}], "center": ["0", "0"], "locus": {"R_hi": "707107/500000", "alpha_hi": "559017/500000", "T": "2909923/1000000", "ccw": [{"mode": "sticks", "bounded": true, "polygon": [["-3909923/500000", "-1"], ["-3/4", "-1"]]}, {"mode": "slides left", "bounded": true, "polygon": [["-3909923/500000", "-1"], ["-3/4", "-1"], ["1/2", "-3/8"], ["1/2", "11/8"], ["-1659923/250000", "-409923/1000000"]]}, {"mode": "slides right", "bounded": true, "polygon": [["-1", "-1"], ["-5/6", "-25/24"], ["-3/4", "-1"]]}], "cw": null, "arm_hi": "4159923/500000"}}''')
# push_square_unknown --locus with its slow distribution: the legs (0, 2, 0, 2) stick at a rate whose centre is at least
# arm_lo = 5.72474 from the pusher's normal line x = 1/2 (v.n / (|omega| |n|), omega bracketed by PU-2).
LOCUS_SLOWEST = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "ccw", "friction": {"lower": "2", "dual_lower": ["-1/2", "0", "0"]}, "votes": [{"lower": "1/2", "dual_lower": ["-1/8", "1/2", "1/8"], "upper": "1/2", "dual_upper": ["1/8", "-1/2", "-1/8"]}, {"lower": "3/2", "dual_lower": ["-3/8", "1/2", "-1/8"], "upper": "3/2", "dual_upper": ["3/8", "-1/2", "1/8"]}, {"lower": "1", "dual_lower": ["-1/4", "1/2", "0"], "upper": "1", "dual_upper": ["1/4", "-1/2", "0"]}], "center": ["0", "0"], "locus": {"R_hi": "707107/500000", "alpha_hi": "559017/500000", "T": "2909923/1000000", "ccw": [{"mode": "sticks", "bounded": true, "polygon": [["-3909923/500000", "-1"], ["-3/4", "-1"]]}, {"mode": "slides left", "bounded": true, "polygon": [["-3909923/500000", "-1"], ["-3/4", "-1"], ["1/2", "-3/8"], ["1/2", "11/8"], ["-1659923/250000", "-409923/1000000"]]}, {"mode": "slides right", "bounded": true, "polygon": [["-1", "-1"], ["-5/6", "-25/24"], ["-3/4", "-1"]]}], "cw": null, "arm_hi": "4159923/500000", "arm_lo": "715593/125000", "slowest": {"forces": ["0", "2", "0", "2"], "mode": "sticks", "bits": 64, "omega": ["6293520118068495/36028797018963968", "6293520118086509/36028797018963968"]}}}''')
LOCUS_TRANSLATES = json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "none", "friction": {"lower": "2"}, "votes": [{"lower": "0", "upper": "0"}, {"lower": "2", "upper": "2"}, {"lower": "-1", "upper": "-1"}], "center": ["0", "0"], "locus": {"R_hi": "707107/500000", "alpha_hi": "559017/500000", "T": "2909923/1000000", "ccw": null, "cw": null}}''')


def tamper(base, path, value):
    """A copy of a certificate with the member at `path` (keys and indices) replaced by value (None: removed)."""
    cert = json.loads(json.dumps(base))
    at = cert
    for k in path[:-1]:
        at = at[k]
    if value is None:
        del at[path[-1]]
    else:
        at[path[-1]] = value
    return cert


def crit(base, **changes):
    cert = json.loads(json.dumps(base))
    cert.update(changes)
    return cert


# three fingers on the L-shaped part's edges 0-3, mu = 1/2, as the engine writes it (GR-2): two cubes certified by four
# wrenches, two triples that never close (every friction-cone edge in a closed half-plane: u = (2, -1) and (1, 2)).
L_TRIPLES = json.loads(r'''{"wrenchkit_certificate": 5, "property": "grasp_regions", "fingers": 3, "mu": "1/2", "edges": [0, 1, 2, 3], "triples": [{"edges": [0, 1, 2], "independent": [["4065393/16777216", "8484751/16777216"], ["8587377/16777216", "13006735/16777216"], ["12208241/16777216", "16627599/16777216"]], "wrenches": ["R0", "L0", "R1", "L2"]}, {"edges": [0, 1, 3], "never": ["2", "-1", "0"]}, {"edges": [0, 2, 3], "independent": [["6649101/16777216", "14322419/16777216"], ["193805/16777216", "7867123/16777216"], ["6976781/16777216", "14650099/16777216"]], "wrenches": ["R0", "L0", "L1", "L2"]}, {"edges": [1, 2, 3], "never": ["1", "2", "0"]}]}''')


def l_triples(**change):
    c = json.loads(json.dumps(L_TRIPLES))
    for k, v in change.items():
        c["triples"][int(k[1:])] = v
    return c


CERTS = [
    ("l_part", "grasp_regions_three", "valid", L_TRIPLES),
    ("l_part", "grasp_regions_three_frictionless", "valid",
     dict(L_TRIPLES, mu="0", triples=[{"edges": t["edges"], "never": "frictionless"} for t in L_TRIPLES["triples"]])),
    ("l_part", "grasp_regions_three_cube_too_big", "invalid:independent|triples[0].independent: at the corner",
     l_triples(t0=dict(L_TRIPLES["triples"][0], independent=[["0", "1"], ["0", "1"], ["0", "1"]]))),
    ("l_part", "grasp_regions_three_never_closes", "invalid:never|triples[0].never: the wrench",
     l_triples(t0={"edges": [0, 1, 2], "never": ["1", "0", "0"]})),
    ("l_part", "grasp_regions_three_frictionless_with_friction", "invalid:never|triples[1].never: \"frictionless\" but mu is 1/2",
     l_triples(t1={"edges": [0, 1, 3], "never": "frictionless"})),
    ("l_part", "grasp_regions_three_triple_missing", "invalid:triples|triples[1]: expected edges [0, 1, 3]",
     dict(L_TRIPLES, triples=L_TRIPLES["triples"][:1] + L_TRIPLES["triples"][2:])),
    ("square_part", "grasp_regions_half", "valid", regions_cert(SQ_PAIRS)),
    ("square_part", "grasp_regions_opposite", "valid", regions_cert([SQ_PAIRS[1]], edges=[0, 2])),
    ("square_part", "grasp_regions_adjacent_at_mu_1", "valid", regions_cert([{"edges": [0, 1], "closed": []}], mu="1", edges=[0, 1])),
    ("square_part", "grasp_regions_independent", "valid",
     regions_cert([dict(SQ_PAIRS[1], independent=[["1/4", "1/2"], ["1/2", "3/4"]])], edges=[0, 2])),
    ("square_part", "grasp_regions_independent_too_big", "invalid:independent|.independent: the corner (0, 1/2) does not close the grasp",
     regions_cert([dict(SQ_PAIRS[1], independent=[["0", "1/2"], ["1/2", "1"]])], edges=[0, 2])),
    ("square_part", "grasp_regions_corner_moved", "invalid:region|pairs[1].closed: not the force-closure region of edges 0 and 2",
     regions_cert([dict(p, closed=[[["1/3", "0"]] + SQ_REGION[1:]]) if p["edges"] == [0, 2] else p for p in SQ_PAIRS])),
    ("square_part", "grasp_regions_pair_missing", "invalid:pairs|pairs[0]: expected edges [0, 1]",
     regions_cert(SQ_PAIRS[1:])),
    ("square_part", "grasp_regions_adjacent_claimed", "invalid:region|pairs[0].closed: not the force-closure region of edges 0 and 1",
     regions_cert([{"edges": [0, 1], "closed": [[["1/2", "1/2"], ["1", "1/2"], ["1", "1"]]]}], mu="1", edges=[0, 1])),
    ("square_part", "grasp_regions_format_4", "invalid:header|property \"grasp_regions\" is format 5",
     dict(regions_cert(SQ_PAIRS), wrenchkit_certificate=4)),
    ("two_fingers_offset", "critical_mu_half", "valid", CRIT_OFFSET),
    # closure's constant signs are the 3x3 minors' (contact 0's left edge has moment -31 + 8 mu: zero at 31/8, inside
    # (7/2, 4], and no 3x3 minor vanishes there)
    ("three_contacts_chirotope", "critical_mu_chirotope", "valid", CRIT_CHIROTOPE),
    ("ladder_gravity", "critical_mu_closure", "valid", CRIT_LADDER_CLOSURE),
    ("ladder_gravity", "critical_mu_one_seventh", "valid", CRIT_LADDER),
    ("two_fingers_same_way", "critical_mu_never", "valid", CRIT_NEVER),
    # the friction margin: each contact's own mu times t; closed for every t above 2/3
    ("two_fingers_offset_own_mu", "friction_margin", "valid", CRIT_MARGIN),
    ("two_fingers_offset_own_mu", "friction_margin_as_common", "invalid:nested|below.certificate: twist: power",
     crit({k: v for k, v in CRIT_MARGIN.items() if k != "scaling"})),
    # balanced only above mu* = 1/2 (at 1/2 the fingers' edges lie on one line, and a pure moment is not balanced)
    ("two_fingers_offset_moment", "critical_mu_half_open", "valid", CRIT_MOMENT),
    ("two_fingers_same_way", "critical_mu_never_balanced", "valid", CRIT_NEVER_LOAD),
    ("two_fingers_offset", "critical_mu_one_third", "invalid:constant|constant: a minor of the edges may change sign between 1/3 and 2/3",
     crit(CRIT_OFFSET, critical_mu={"lower": "1/3", "upper": "1/3"}, below=dict(CRIT_OFFSET["below"], mu="1/3"))),
    ("two_fingers_offset", "critical_mu_bracket_off", "invalid:bracket|critical_mu: a bracket is [below.mu, above.mu] = [1/2, 2/3]",
     crit({k: v for k, v in CRIT_OFFSET.items() if k != "constant"}, critical_mu={"lower": "2/5", "upper": "2/3"})),
    ("two_fingers_offset", "critical_mu_above_not_closed", "invalid:nested|above.certificate: combination: the weighted sum of the generators is",
     crit(CRIT_OFFSET, above=dict(CRIT_OFFSET["above"], mu="1/3"))),
    ("two_fingers_offset", "critical_mu_equilibrium_without_load", 'invalid:no load|of: "equilibrium", but the scene has no load',
     crit(CRIT_OFFSET, of="equilibrium")),
    ("two_fingers_same_way", "critical_mu_never_sideways", "invalid:limit_twist|limit_twist: power",
     crit(CRIT_NEVER, limit_twist=["0", "1", "0"])),
    ("ladder_gravity", "critical_mu_nested_format_4", "invalid:nested|above.certificate: expected a certificate of \"equilibrium\" in format 1, 2 or 3",
     crit(CRIT_LADDER, above=dict(CRIT_LADDER["above"], certificate=dict(CRIT_LADDER["above"]["certificate"], wrenchkit_certificate=4)))),
    # GraspIt!'s torque scale 1/sqrt 2 (the square's largest radius): epsilon^2 = 1/200, bracketed with the scale's error
    ("square_side_middles", "quality_graspit", "valid", GRASPIT_SQUARE),
    ("square_side_middles", "quality_graspit_scale_off", "invalid:torque|torque_scale: 1/sqrt(2) is not within",
     dict(GRASPIT_SQUARE, torque_scale="7/10")),
    ("two_fingers_mu1", "quality_l1", "valid",
     quality("L1", "as-given", {"lower": "577/1000", "upper": "289/500", "squared": "1/3"}, scales=EXACT,
             boundary=TETRA, nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_unit_force", "valid",
     quality("L1", "unit-force", {"lower": "2/5", "upper": "21/50"}, scales=ROOT2, boundary=TETRA, nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_linf", "valid",
     quality("Linf", "as-given", {"lower": "4/5", "upper": "41/50", "squared": "2/3"}, scales=EXACT, normal=["-2", "1", "-1"])),
    ("two_fingers_mu0", "quality_zero", "valid",
     quality("L1", "unit-normal", {"lower": "0", "upper": "0", "squared": "0"}, twist=["0", "0", "1"])),
    ("two_fingers_mu1", "quality_open_surface", "invalid:surface|has no reverse: the surface is not closed",
     quality("L1", "as-given", {"lower": "577/1000", "upper": "289/500", "squared": "1/3"}, scales=EXACT,
             boundary=TETRA[:3], nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_inward_triangle", "invalid:orientation|the origin is not strictly behind the triangle",
     quality("L1", "as-given", {"lower": "577/1000", "upper": "289/500", "squared": "1/3"}, scales=EXACT,
             boundary=[[0, 2, 1]] + TETRA[1:], nearest=[0, 3, 1])),
    ("two_fingers_mu1", "quality_squared_wrong", "invalid:squared|epsilon.squared: 1/4 is not 1/3",
     quality("L1", "as-given", {"lower": "1/2", "upper": "289/500", "squared": "1/4"}, scales=EXACT, boundary=TETRA,
             nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_lower_too_high", "invalid:lower|epsilon.lower: 3/5 is above",
     quality("L1", "as-given", {"lower": "3/5", "upper": "3/5", "squared": "1/3"}, scales=EXACT, boundary=TETRA,
             nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_scale_not_exact", "invalid:scale|scales[0].scale: 181/256 is not 1/",
     quality("L1", "unit-force", {"lower": "2/5", "upper": "21/50", "squared": "1/6"},
             scales=[{"scale": "181/256", "error": "0", "bound": "7/4"}] * 2, boundary=TETRA, nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_bound_short", "invalid:bound|scales[0].bound: 3/2 is shorter than the edge",
     quality("L1", "unit-force", {"lower": "2/5", "upper": "21/50"},
             scales=[{"scale": "181/256", "error": "1/256", "bound": "3/2"}] * 2, boundary=TETRA, nearest=[0, 1, 2])),
    ("two_fingers_mu1", "quality_linf_not_nearest", "invalid:normal|normal: not the normal of a facet nearest the origin",
     quality("Linf", "as-given", {"lower": "4/5", "upper": "41/50", "squared": "2/3"}, scales=EXACT, normal=["1", "1", "-1"])),
    ("two_fingers_mu1", "quality_zero_for_a_closed_grasp", "invalid:power|twist: power",
     quality("L1", "as-given", {"lower": "0", "upper": "0", "squared": "0"}, twist=["0", "0", "1"])),
    ("two_fingers_mu1", "quality_format_3", "invalid:header|property \"quality\" is format 4",
     dict(quality("L1", "as-given", {"lower": "577/1000", "upper": "289/500", "squared": "1/3"}, scales=EXACT,
                  boundary=TETRA, nearest=[0, 1, 2]), wrenchkit_certificate=3)),
    # block in a corner: not in force closure (nor form closure)
    ("block_corner_mu0", "translate_up", "valid",
     negative("force_closure", ["0", "1", "0"], {"label": "infinity", "direction": ["-1", "0"]})),
    ("block_corner_mu0", "form_translate_up", "valid", negative("form_closure", ["0", "1", "0"])),
    ("block_corner_mu0", "clockwise_about_1_0", "valid",
     negative("force_closure", ["0", "1", "-1"], {"label": "-", "point": ["1", "0"]})),
    ("block_corner_mu0", "counter_clockwise_about_0_1", "valid",
     negative("force_closure", ["2/2", "0", "1"], {"label": "+", "point": ["0", "1"]})),
    ("block_corner_mu0", "twist_down", "invalid:power|twist: power -1 against contacts[0] edge normal",
     negative("force_closure", ["0", "-1", "0"])),
    ("block_corner_mu0", "zero_twist", "invalid:zero twist|twist: the zero twist proves nothing", negative("force_closure", ["0", "0", "-0"])),
    ("block_corner_mu0", "wrong_reading_label", "invalid:label|reading.label: \"+\" does not match the twist, whose label is \"infinity\"",
     negative("force_closure", ["0", "1", "0"], {"label": "+", "point": ["0", "0"]})),
    ("block_corner_mu0", "wrong_reading_direction", "invalid:direction|reading.direction: (1, 0) is not a positive multiple of (-vy, vx) = (-1, 0)",
     negative("force_closure", ["0", "1", "0"], {"label": "infinity", "direction": ["1", "0"]})),
    ("block_corner_mu0", "wrong_reading_point", "invalid:point|reading.point: (1, 1) is not the rotation centre (1, 0) of the twist",
     negative("force_closure", ["0", "1", "-1"], {"label": "-", "point": ["1", "1"]})),
    ("block_corner_mu0", "claims_closure", "invalid:sum|combination: the weighted sum of the generators is",
     positive("force_closure", comb((0, "normal", "1"), (2, "normal", "1"), (3, "normal", "1")),
              refs((0, "normal"), (2, "normal"), (3, "normal")))),

    # square held by crossed couples: form closure
    ("square_crossed_couples", "form", "valid", positive("form_closure", SQUARE, SQUARE_IND)),
    ("square_crossed_couples", "force", "valid", positive("force_closure", SQUARE, SQUARE_IND)),
    ("square_crossed_couples", "weights_not_lowest_terms", "valid",
     positive("form_closure", comb((3, "normal", "2/4"), (1, "normal", "3/6"), (2, "normal", "1/2"),
                                   (0, "normal", "50/100")), refs((1, "normal"), (2, "normal"), (3, "normal")))),
    ("square_crossed_couples", "zero_weight", 'invalid:weight|combination[1].weight: "0" is not strictly positive',
     positive("form_closure", comb((0, "normal", "1"), (1, "normal", "0"), (2, "normal", "1"), (3, "normal", "1")),
              SQUARE_IND)),
    ("square_crossed_couples", "negative_weight", 'invalid:weight|combination[0].weight: "-1" is not strictly positive',
     positive("form_closure", comb((0, "normal", "-1"), (1, "normal", "-1"), (2, "normal", "-1"), (3, "normal", "-1")),
              SQUARE_IND)),
    ("square_crossed_couples", "unbalanced_weights", "invalid:sum|combination: the weighted sum of the generators is (0, -1, -1/2), not (0, 0, 0)",
     positive("form_closure", comb((0, "normal", "1"), (1, "normal", "2"), (2, "normal", "1"), (3, "normal", "1")),
              SQUARE_IND)),
    ("square_crossed_couples", "dependent_triple", "invalid:determinant|independent: the three generators are linearly dependent",
     positive("form_closure", SQUARE, refs((0, "normal"), (0, "normal"), (1, "normal")))),
    ("square_crossed_couples", "index_out_of_range", "invalid:reference|combination[3].contact: index 4 is out of range (the scene has 4 contacts)",
     positive("form_closure", comb((0, "normal", "1"), (1, "normal", "1"), (2, "normal", "1"), (4, "normal", "1")),
              SQUARE_IND)),
    ("square_crossed_couples", "huge_index", "invalid:reference|independent[2].contact: index 123456789012345678901234567890 is out of range",
     positive("form_closure", SQUARE, refs((0, "normal"), (1, "normal"), (123456789012345678901234567890, "normal")))),
    ("square_crossed_couples", "left_edge_frictionless", 'invalid:reference|combination[0].edge: contacts[0] has no edge "left" under the friction reading (it has "normal")',
     positive("force_closure", comb((0, "left", "1"), (1, "normal", "1"), (2, "normal", "1"), (3, "normal", "1")),
              SQUARE_IND)),
    ("square_crossed_couples", "duplicate_generator", "invalid:duplicate|combination[4]: contacts[0] edge normal appears twice (also at combination[0])",
     positive("form_closure", comb((0, "normal", "1/2"), (1, "normal", "1"), (2, "normal", "1"), (3, "normal", "1"),
                                   (0, "normal", "1/2")), SQUARE_IND)),
    ("square_crossed_couples", "unknown_key", 'invalid:unknown key|unknown key "comment"',
     dict(positive("form_closure", SQUARE, SQUARE_IND), comment="not part of format v1")),
    ("square_crossed_couples", "zero_denominator_weight", 'invalid:malformed|combination[0].weight: "1/0" is not a rational',
     positive("form_closure", comb((0, "normal", "1/0"), (1, "normal", "1"), (2, "normal", "1"), (3, "normal", "1")),
              SQUARE_IND)),
    ("square_crossed_couples", "twist_with_holds_true", 'invalid:keys|key "twist" is not allowed when "holds" is true',
     dict(positive("form_closure", SQUARE, SQUARE_IND), twist=["0", "1", "0"])),

    # two fingers with friction: force closure, not form closure
    ("two_finger_mu_1_2", "force", "valid", positive("force_closure", TWO_FINGER, TWO_FINGER_IND)),
    ("two_finger_mu_1_2", "force_scaled", "valid",
     positive("force_closure", comb((1, "right", "7/3"), (1, "left", "7/3"), (0, "right", "14/6"), (0, "left", "7/3")),
              refs((1, "right"), (0, "left"), (0, "right")))),
    ("two_finger_mu_1_2", "form_translate_up", "valid",
     negative("form_closure", ["0", "1", "0"], {"label": "infinity", "direction": ["-2", "0"]})),
    ("two_finger_mu_1_2", "normal_edge_frictional", 'invalid:reference|combination[0].edge: contacts[0] has no edge "normal" under the friction reading (it has "left" or "right")',
     positive("force_closure", comb((0, "normal", "1"), (0, "right", "1"), (1, "left", "1"), (1, "right", "1")),
              TWO_FINGER_IND)),
    ("two_finger_mu_1_2", "translate_up_under_friction", "invalid:power|twist: power -1/2 against contacts[0] edge right",
     negative("force_closure", ["0", "1", "0"])),
    ("two_finger_mu_1_2", "form_claimed", "invalid:determinant|independent: the three generators are linearly dependent",
     positive("form_closure", comb((0, "normal", "1"), (1, "normal", "1")),
              refs((0, "normal"), (1, "normal"), (0, "normal")))),

    # triangle: force closure with mu = 1/10; frictionless reading has rank 2 (normals meet at G = (1,1))
    ("triangle_mu_1_10", "force", "valid",
     positive("force_closure", comb(*[(c, e, "1") for c, e in TRIANGLE_EDGES]),
              refs((0, "left"), (0, "right"), (1, "left")))),
    ("triangle_mu_1_10", "force_uneven", "valid", None),  # weights computed below
    ("triangle_mu_1_10", "form_rotation_about_G", "valid",
     negative("form_closure", ["1", "-1", "1"], {"label": "+", "point": ["1", "1"]})),
    ("triangle_mu_1_10", "form_rotation_about_G_clockwise", "valid",
     negative("form_closure", ["-2", "2", "-2"], {"label": "-", "point": ["2/2", "1"]})),
    ("triangle_mu_1_10", "force_rotation_about_G", "invalid:power|twist: power -1/10 against contacts[0] edge left",
     negative("force_closure", ["1", "-1", "1"], {"label": "+", "point": ["1", "1"]})),
    ("triangle_mu_1_10", "form_rank_2", "invalid:determinant|independent: the three generators are linearly dependent",
     positive("form_closure", comb((0, "normal", "1"), (1, "normal", "1"), (2, "normal", "1")),
              refs((0, "normal"), (1, "normal"), (2, "normal")))),

    # block in a corner under a load (theory.md section 9): equilibrium, reading friction
    ("block_corner_mu0", "equilibrium", "valid",  # load (0,-1) at (1/2,1/2): half on each floor normal
     equilibrium_true(comb((0, "normal", "1/2"), (1, "normal", "1/2")))),
    ("block_corner_mu_1_2_gravity", "equilibrium", "valid", None),  # found by balancing_weights()
    ("block_corner_mu_1_2_gravity", "equilibrium_with_wall", "valid", None),
    ("block_corner_mu_1_2_gravity", "equilibrium_four_floor_edges", "valid",
     equilibrium_true(comb((0, "left", "1/4"), (0, "right", "1/4"), (1, "left", "1/4"), (1, "right", "1/4")))),
    ("block_corner_mu_1_2_gravity", "unbalanced_weights",
     "invalid:sum|combination: the weighted sum of the generators plus the load is (0, 1/3, 1/6), not (0, 0, 0)",
     equilibrium_true(comb((0, "left", "1/3"), (0, "right", "1/3"), (1, "left", "1/3"), (1, "right", "1/3")))),
    ("block_corner_mu_1_2_gravity", "negative_weight", None, None),  # expected and certificate computed
    ("block_corner_mu_1_2_gravity", "independent_present",
     'invalid:keys|key "independent" is not allowed when "property" is "equilibrium"', None),
    ("block_corner_mu_1_2_gravity", "twist_against_balanced_load", "invalid:power|twist: power -1/2 against contacts[2] edge right",
     negative("equilibrium", ["0", "1", "0"])),
    ("block_corner_mu_1_2_push", "equilibrium", "valid", None),
    ("block_corner_mu_1_2_pull", "not_balanced_translation", "valid",
     negative("equilibrium", ["1", "1", "0"], {"label": "infinity", "direction": ["-1", "1"]})),
    ("block_corner_mu_1_2_pull", "not_balanced_rotation", "valid",
     negative("equilibrium", ["2", "1", "1"], {"label": "+", "point": ["-1", "2"]})),
    ("block_corner_mu_1_2_pull", "push_weights", "invalid:sum|combination: the weighted sum of the generators plus the load is (2, 0, -1), not (0, 0, 0)",
     None),  # the weights that balance the push: the load's sign matters
    ("block_corner_mu_1_2_torque", "not_balanced", "valid",
     negative("equilibrium", ["4/2", "1", "1"], {"label": "+", "point": ["-1", "2"]})),
    ("block_corner_mu_1_2_torque", "zero_power_against_load", "invalid:load power|twist: power against the load is 0, not > 0",
     negative("equilibrium", ["1", "1", "0"])),
    ("square_crossed_couples", "equilibrium_without_load", 'invalid:no load|property: "equilibrium" needs a scene with a load',
     equilibrium_true(SQUARE)),

    # wrench generators: the same under both readings
    ("wrench_generators", "force", "valid", positive("force_closure", WRENCHES, WRENCHES_IND)),
    ("wrench_generators", "form", "valid", positive("form_closure", WRENCHES, WRENCHES_IND)),
    ("wrench_generators", "normal_edge_on_wrench", 'invalid:reference|combination[0].edge: contacts[0] has no edge "normal" under the friction reading (it has "wrench")',
     positive("force_closure", comb((0, "normal", "1"), (1, "wrench", "1"), (2, "wrench", "1"), (3, "wrench", "1")),
              WRENCHES_IND)),

    # sliding (certificate-format.md section 6)
    ("table_four_legs", "sticks_for_every", "valid", TABLE_STICKS),
    ("table_four_legs", "slides_for_every", "valid", TABLE_SLIDES),
    ("table_four_legs", "depends", "valid", TABLE_DEPENDS),
    ("barbell_known", "sticks", "valid", motion("sticks", [F(1, 4), 0, 0], support_forces=[["1/8", "0"], ["1/8", "0"]])),
    ("barbell_known", "slides", "valid", motion("slides", [1, 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1"])),
    ("table_four_legs", "force_outside_disc", "invalid:stick|vertices[1].support_forces[1]: |g|^2 = 5/16 is not less than (mu f)^2 = 1/4",
     dict(TABLE_STICKS, vertices=[TABLE_STICKS["vertices"][0],
                                  stick_witness(["0", "1/2", "0", "1/2"], [["0", "0"], ["-1/4", "1/2"], ["0", "0"], ["3/4", "-1/2"]])])),
    ("table_four_legs", "missing_vertex", "invalid:vertex|vertices: the vertex (0, 1/2, 0, 1/2) of the admissible distributions has no witness",
     dict(TABLE_STICKS, vertices=TABLE_STICKS["vertices"][:1])),
    ("table_four_legs", "distribution_outside_F", "invalid:F|sticking.distribution: sum f_i r_i is (1, 0), not W c = (0, 0)",
     dict(TABLE_DEPENDS, sticking=stick_witness(["1/2", "0", "0", "1/2"], TABLE_DEPENDS["sticking"]["support_forces"]))),
    ("table_four_legs", "speed_bound_too_small", "invalid:speed|speed_bounds[3]: u^2 = 9801/10000 is less than |v_i(q)|^2 = 1",
     dict(TABLE_SLIDES, speed_bounds=["1", "1", "1", "99/100"])),
    ("table_four_legs", "dual_violated", "invalid:dual|dual: mu_i u_i = 1 is more than y0 + yx x_i + yy y_i = 9/10 at support.points[0]",
     dict(TABLE_SLIDES, dual=["9/10", "0", "0"])),
    ("table_four_legs", "slides_without_dual", 'invalid:keys|missing required key "dual"',
     {k: v for k, v in TABLE_SLIDES.items() if k != "dual"}),
    ("barbell_known", "slides_on_surface", "valid", motion("slides", [F(1, 2), 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1"])),
    # Format 3 (section 6.6): the surface is "impending". A facet of Fig. 6.15: the rotation about the support point
    # (0, 1), q = (1, 0, 1), speeds 2 and 0, power 1/4 + 1/4 = 1/2 = (1/4) 2; the force (1/4, 0) at (0, -1) on its
    # circle carries (1/4, 0, 1/4). A translation at exactly mu W: (1/2, 0, 0), speeds 1, 1.
    ("barbell_known", "impending_facet", "valid",
     motion3("impending", [F(1, 4), 0, F(1, 4)], support_forces=[["1/4", "0"], ["0", "0"]], twist=["1", "0", "1"],
             speed_bounds=["2", "0"])),
    ("barbell_known", "impending_translation", "valid",
     motion3("impending", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]], twist=["1", "0", "0"],
             speed_bounds=["1", "1"])),
    # (1/2, 0, 0) is a vertex of Fig. 6.15 (both forces saturated across the barbell): its normals are a wedge, and the
    # rotation (2, 0, 1) about (0, 2) is one of them as well: speeds 3 and 1, power 1 = (1/4)(3 + 1).
    ("barbell_known", "impending_vertex_wedge", "valid",
     motion3("impending", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]], twist=["2", "0", "1"],
             speed_bounds=["3", "1"])),
    # A smooth point: the rotation about (4/3, 0), q = (0, -4, 3), moves both points at the Pythagorean speed 5; each
    # force saturated along its velocity, (1/4)(3/5, -4/5) and (1/4)(-3/5, -4/5), carries (0, -2/5, 3/10), and the
    # power 8/5 + 9/10 = 5/2 = (1/4)(5 + 5). (The engine writes this certificate, in exact and hybrid mode.)
    ("barbell_known", "impending_smooth", "valid",
     motion3("impending", [0, F(-2, 5), F(3, 10)], support_forces=[["3/20", "-1/5"], ["-3/20", "-1/5"]],
             twist=["0", "-4", "3"], speed_bounds=["5", "5"])),
    ("barbell_known", "slides_on_surface_in_format_3", "invalid:power|only equals sum mu_i f_i u_i = 1/2",
     motion3("slides", [F(1, 2), 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1"])),
    ("barbell_known", "impending_in_format_1", 'invalid:version|motion: "impending" is a claim of format 3',
     motion("impending", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]], twist=["1", "0", "0"],
            speed_bounds=["1", "1"])),
    ("barbell_known", "impending_force_outside_disc", "invalid:stick|support_forces[0]",
     motion3("impending", [F(1, 2), 0, F(1, 2)], support_forces=[["1/2", "0"], ["0", "0"]], twist=["1", "0", "1"],
             speed_bounds=["2", "0"])),
    ("barbell_known", "impending_power_short", "invalid:power|twist: power q.p = 1/4 is less than sum mu_i f_i u_i = 1/2",
     motion3("impending", [F(1, 4), 0, F(1, 4)], support_forces=[["1/4", "0"], ["0", "0"]], twist=["1", "0", "0"],
             speed_bounds=["1", "1"])),
    # The version, the twist and its speeds of an impending claim: "impending" in format 2 is rejected as in format 1;
    # the zero twist meets every bound and proves nothing. The translation (1, 1, 0) moves both points at sqrt(2), which
    # no rational bound equals: rounded down (7/5) it is not a bound, rounded up (3/2) the power 1/2 of (1/2, 0, 0)
    # falls short of (1/4)(3/2) 2 = 3/4. (q.p = h(q) forces u_i = |v_i(q)|: SL-1 section 7.)
    ("barbell_known", "impending_in_format_2", 'invalid:version|motion: "impending" is a claim of format 3',
     motion2("impending", [F(1, 4), 0, F(1, 4)], support_forces=[["1/4", "0"], ["0", "0"]], twist=["1", "0", "1"],
             speed_bounds=["2", "0"])),
    ("barbell_known", "impending_zero_twist", "invalid:zero twist|twist: the zero twist",
     motion3("impending", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]], twist=["0", "0", "0"],
             speed_bounds=["0", "0"])),
    ("barbell_known", "impending_speed_rounded_down", "invalid:speed|speed_bounds[0]: u^2 = 49/25 is less than |v_i(q)|^2 = 2",
     motion3("impending", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]], twist=["1", "1", "0"],
             speed_bounds=["7/5", "7/5"])),
    ("barbell_known", "impending_speed_rounded_up", "invalid:power|twist: power q.p = 1/2 is less than sum mu_i f_i u_i = 3/4",
     motion3("impending", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]], twist=["1", "1", "0"],
             speed_bounds=["3/2", "3/2"])),
    # The table at exactly mu W along x: every vertex of F (the two diagonals) carries (1, 0, 0) with forces (1/2, 0) on
    # their circles, and q = (1, 0, 0) with the dual (1, 0, 0) bounds every distribution's power by W = 1 = q.p.
    ("table_four_legs", "impending_for_every", "valid",
     motion3("impending", [1, 0, 0],
             vertices=[stick_witness(["1/2", "0", "1/2", "0"], [["1/2", "0"], ["0", "0"], ["1/2", "0"], ["0", "0"]]),
                       stick_witness(["0", "1/2", "0", "1/2"], [["0", "0"], ["1/2", "0"], ["0", "0"], ["1/2", "0"]])],
             twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"], dual=["1", "0", "0"])),
    ("table_four_legs", "impending_missing_vertex", "invalid:vertex|vertices: the vertex (0, 1/2, 0, 1/2) of the admissible distributions has no witness",
     motion3("impending", [1, 0, 0],
             vertices=[stick_witness(["1/2", "0", "1/2", "0"], [["1/2", "0"], ["0", "0"], ["1/2", "0"], ["0", "0"]])],
             twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"], dual=["1", "0", "0"])),
    ("barbell_known", "power_below_bound", "invalid:power|twist: power q.p = 2/5 is less than sum mu_i f_i u_i = 1/2",
     motion("slides", [F(2, 5), 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1"])),
    ("barbell_known", "g_on_circle", "invalid:stick|support_forces[0]: |g|^2 = 1/16 is not less than (mu f)^2 = 1/16",
     motion("sticks", [F(1, 2), 0, 0], support_forces=[["1/4", "0"], ["1/4", "0"]])),
    ("barbell_known", "depends_on_known", 'invalid:depends known|motion: "depends" needs a support with an unknown distribution',
     dict(motion("depends", [F(1, 2), F(1, 2), F(9, 10)]), sticking=TABLE_DEPENDS["sticking"], sliding=TABLE_DEPENDS["sliding"])),
    # Fixtures (section 7). The push (-1, 1/4) at (1,0) is w_L = (-1, 1/4, 1/4): the pin takes -1 along x, and
    # the two right legs each give (0, -1/8), on their circles (|g| = mu f = 1/8): held (a hold is closed).
    ("fixture_pin_push", "holds", "valid",
     hold(True, combination=comb((0, "normal", "1")), support_forces=[["0", "-1/8"], ["0", "0"], ["0", "0"], ["0", "-1/8"]])),
    ("fixture_pin_push", "force_outside_disc", "invalid:disc|support_forces[0]: |g|^2 = 1/16 is not at most (mu f)^2 = 1/64",
     hold(True, combination=comb((0, "normal", "1")), support_forces=[["0", "-1/4"], ["0", "0"], ["0", "0"], ["0", "0"]])),
    ("fixture_pin_push", "unbalanced", "invalid:sum|combination: the contact forces, the support forces and the load sum to (-1/2, 0, 0), not (0, 0, 0)",
     hold(True, combination=comb((0, "normal", "1/2")), support_forces=[["0", "-1/8"], ["0", "0"], ["0", "0"], ["0", "-1/8"]])),
    ("fixture_pin_push", "depends_on_known", 'invalid:depends known|holds: "depends" needs a support with an unknown distribution',
     hold("depends", holding=hold_witness(["1/4"] * 4, [], [["0", "0"]] * 4),
          failing={"distribution": ["1/4"] * 4, "twist": ["0", "1", "1"], "speed_bounds": ["9/4", "1", "1", "9/4"]})),
    # The lift (0, 1) at (1,0) is w_L = (0, 1, 1): the counter-clockwise rotation about the pin, twist (0, 1, 1),
    # keeps the pin's power 0; its speeds at the legs are sqrt(5), 1, 1, sqrt(5) <= 9/4, so friction resists at
    # most (1/8)(9/4 + 1 + 1 + 9/4) = 13/16 < t.w_L = 2.
    ("fixture_pin_lift", "moves", "valid",
     hold(False, twist=["0", "1", "1"], reading={"label": "+", "point": ["-1", "0"]}, speed_bounds=["9/4", "1", "1", "9/4"])),
    ("fixture_pin_lift", "into_the_pin", "invalid:power|twist: power -1 against contacts[0] edge normal",
     hold(False, twist=["-1", "0", "0"], speed_bounds=["1", "1", "1", "1"])),
    ("fixture_pin_lift", "speed_bound_too_small", "invalid:speed|speed_bounds[0]: u^2 = 4 is less than |v_i(q)|^2 = 5",
     hold(False, twist=["0", "1", "1"], speed_bounds=["2", "1", "1", "9/4"])),
    ("fixture_pin_lift", "support_forces_on_failure", 'invalid:keys|key "support_forces" is not allowed when "holds" is false',
     hold(False, twist=["0", "1", "1"], speed_bounds=["9/4", "1", "1", "9/4"], support_forces=[["0", "0"]] * 4)),
    # The pull (1/2, 0) at the centre: away from the pin; the four legs just hold it, each (-1/8, 0) on its circle.
    # The translation (1, 0, 0) meets exactly the friction bound 4 (1/8) 1 = 1/2 = t.w_L: a stick/slide certificate
    # would call that "slides"; a hold needs more power than the bound, so it proves nothing here.
    ("fixture_pin_pull", "holds_on_the_boundary", "valid",
     hold(True, combination=[], support_forces=[["-1/8", "0"]] * 4)),
    ("fixture_pin_pull", "power_equals_bound", "invalid:power|twist: power against the load t.w_L = 1/2 is not more than sum mu_i f_i u_i = 1/2",
     hold(False, twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"])),
    # Format 3 (section 7.6): the same pull is "impending" — the closed witness above and the translation whose power
    # meets the bound, together — and "holds": true now means with margin, which the forces on their circles are not.
    ("fixture_pin_pull", "impending", "valid",
     hold3("impending", combination=[], support_forces=[["-1/8", "0"]] * 4, twist=["1", "0", "0"],
           speed_bounds=["1", "1", "1", "1"])),
    ("fixture_pin_pull", "holds_v3_without_margin", "invalid:margin|combination: the load is held, but with no margin",
     hold3(True, combination=[], support_forces=[["-1/8", "0"]] * 4)),
    ("fixture_pin_pull", "impending_in_format_2", 'invalid:version|holds: "impending" is a claim of format 3',
     dict(hold3("impending", combination=[], support_forces=[["-1/8", "0"]] * 4, twist=["1", "0", "0"],
                speed_bounds=["1", "1", "1", "1"]), wrenchkit_certificate=2)),
    ("fixture_pin_pull", "impending_power_short", "invalid:power|twist: power against the load t.w_L = 0 is not at least sum mu_i f_i u_i = 1/2",
     hold3("impending", combination=[], support_forces=[["-1/8", "0"]] * 4, twist=["0", "1", "0"],
           speed_bounds=["1", "1", "1", "1"])),
    ("fixture_pin_pull", "impending_zero_twist", "invalid:zero twist|twist: the zero twist",
     hold3("impending", combination=[], support_forces=[["-1/8", "0"]] * 4, twist=["0", "0", "0"],
           speed_bounds=["0", "0", "0", "0"])),
    # The pull carried by the two right legs alone, (-1/4, 0) each (their moments cancel): outside the discs of
    # radius 1/8, so the witness is not in the closed set, whatever the twist shows.
    ("fixture_pin_pull", "impending_force_outside_disc", "invalid:disc|support_forces[0]: |g|^2 = 1/16 is not at most (mu f)^2 = 1/64",
     hold3("impending", combination=[], support_forces=[["-1/4", "0"], ["0", "0"], ["0", "0"], ["-1/4", "0"]],
           twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"])),
    # The push (-1, 1/4) at (1, 0) held with margin in format 3: the pin takes the push along x; the legs carry
    # (0, -1/4) with the moment -1/4 by (±1/16, -1/16) each, |g|^2 = 1/128 < 1/64 strictly inside their discs; the
    # pin's normal and the legs' span make R^3.
    ("fixture_pin_push", "holds_with_margin", "valid",
     hold3(True, combination=comb((0, "normal", "1")),
           support_forces=[["1/16", "-1/16"], ["1/16", "-1/16"], ["-1/16", "-1/16"], ["-1/16", "-1/16"]])),
    # No support: hold is equilibrium (section 3.3): the floor's two cone edges carry the block's weight.
    ("block_corner_mu_1_2_gravity", "hold_without_support", "valid", None),
    ("block_corner_mu_1_2_gravity", "hold_with_support_forces", 'invalid:keys|key "support_forces" is not allowed when "holds" is true and the scene has no support',
     None),
    # The pinned table, every leg force unknown: F's vertices are the diagonal barbells (1/2, 0, 1/2, 0) and
    # (0, 1/2, 0, 1/2). (1/2, 0, 0): each holds it with the forces (-1/4, 0) at its two legs.
    ("table_pinned_nudged", "holds_for_every", "valid",
     hold(True, vertices=[hold_witness(["1/2", "0", "1/2", "0"], [], [["-1/4", "0"], ["0", "0"], ["-1/4", "0"], ["0", "0"]]),
                          hold_witness(["0", "1/2", "0", "1/2"], [], [["0", "0"], ["-1/4", "0"], ["0", "0"], ["-1/4", "0"]])])),
    ("table_pinned_nudged", "missing_vertex", "invalid:vertex|vertices: the vertex (0, 1/2, 0, 1/2) of the admissible distributions has no witness",
     hold(True, vertices=[hold_witness(["1/2", "0", "1/2", "0"], [], [["-1/4", "0"], ["0", "0"], ["-1/4", "0"], ["0", "0"]])])),
    # (3/2, 0, 0): the translation (1, 0, 0) leaves the pin (power 1 >= 0); every speed is 1 and mu_i u_i = 1 <= y0 = 1,
    # so friction resists at most y0 W = 1 < 3/2 under every distribution.
    ("table_pinned_shoved", "fails_for_every", "valid",
     hold(False, twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"], dual=["1", "0", "0"])),
    ("table_pinned_shoved", "fails_without_dual", 'invalid:keys|missing required key "dual"',
     hold(False, twist=["1", "0", "0"], speed_bounds=["1", "1", "1", "1"])),
    # (1/2, 1/2, 9/10): held by the diagonal (1,1)-(-1,-1) (the stick witness of section 6.3, negated: forces on
    # the body), not by the other: the rotation (1, 1, 1) about (-1, 1) leaves the pin (power 1), t.w_L = 19/10 and
    # friction resists at most (1/2)(0 + 17/6) = 17/12.
    ("table_pinned_pushed", "depends", "valid",
     hold("depends", holding=hold_witness(["1/2", "0", "1/2", "0"], [], [["-1/40", "-19/40"], ["0", "0"], ["-19/40", "-1/40"], ["0", "0"]]),
          failing={"distribution": ["0", "1/2", "0", "1/2"], "twist": ["1", "1", "1"], "speed_bounds": ["2", "0", "2", "17/6"]})),
    ("table_pinned_pushed", "holding_outside_F", "invalid:F|holding.distribution: the forces sum to 1/2, not the weight 1",
     hold("depends", holding=hold_witness(["1/4", "0", "1/4", "0"], [], [["-1/40", "-19/40"], ["0", "0"], ["-19/40", "-1/40"], ["0", "0"]]),
          failing={"distribution": ["0", "1/2", "0", "1/2"], "twist": ["1", "1", "1"], "speed_bounds": ["2", "0", "2", "17/6"]})),
    ("barbell_known", "vertices_on_known", 'invalid:keys|key "vertices" is not allowed when "motion" is "sticks" and every support force is given',
     motion("sticks", [F(1, 4), 0, 0], vertices=[stick_witness(["1/2", "1/2"], [["1/8", "0"], ["1/8", "0"]])])),

    # support regions (certificate-format.md section 6.4)
    ("square_region", "sticks", "valid", SQUARE_STICKS),
    ("square_region", "slides", "valid", SQUARE_SLIDES),
    ("square_region", "slides_hanging_vertices", "valid", SQUARE_SLIDES_HANGING),
    ("square_frame", "sticks", "valid", FRAME_STICKS),
    ("square_frame", "slides_on_surface", "valid", FRAME_SLIDES),
    ("square_region", "force_outside_disc", "invalid:stick|regions[0].forces[0]: |g|^2 = 45/128 is not less than (mu F)^2 = 1/4",
     dict(SQUARE_STICKS, load=["1/2", "0", "3/8"], regions=[block(SQUARE_2, forces=[["9/16", "3/16"], ["-1/16", "-3/16"]])])),
    ("square_region", "cell_outside", "invalid:tiling|regions[0]: the cells do not tile support.regions[0]",
     dict(SQUARE_STICKS, regions=[block(([[-1, -1], [1, -1], [1, 1], [-1, 1], [2, 1]], [[0, 1, 2], [0, 2, 3], [1, 4, 2]]),
                                        forces=[["7/16", "3/16"], ["1/16", "-3/16"], ["0", "0"]])])),
    ("square_region", "cell_missing", "invalid:tiling|regions[0]: the cells do not tile support.regions[0]",
     dict(SQUARE_STICKS, load=["7/16", "3/16", "1/6"], regions=[block(([[-1, -1], [1, -1], [1, 1], [-1, 1]], [[0, 1, 2]]),
                                                                      forces=[["7/16", "3/16"]])])),
    ("square_region", "cells_overlap", "invalid:tiling|regions[0]: the cells do not tile support.regions[0]",
     dict(SQUARE_STICKS, load=["1/2", "0", "1/6"], regions=[block(([[-1, -1], [1, -1], [1, 1], [-1, 1]], [[0, 1, 2], [0, 2, 3], [1, 2, 3]]),
                                                                  forces=[["1/4", "0"], ["1/4", "0"], ["0", "0"]])])),
    ("square_region", "clockwise_cell", "invalid:tiling|regions[0].triangles[1]: not counter-clockwise with a positive area",
     dict(SQUARE_STICKS, regions=[block(([[-1, -1], [1, -1], [1, 1], [-1, 1]], [[0, 1, 2], [0, 3, 2]]),
                                        forces=[["7/16", "3/16"], ["1/16", "-3/16"]])])),
    ("square_region", "index_out_of_range", "invalid:tiling|regions[0].triangles[1]: vertex index 4 out of range (4 vertices)",
     dict(SQUARE_STICKS, regions=[block(([[-1, -1], [1, -1], [1, 1], [-1, 1]], [[0, 1, 2], [0, 2, 4]]),
                                        forces=[["7/16", "3/16"], ["1/16", "-3/16"]])])),
    ("square_region", "speed_bound_too_small", "invalid:speed|regions[0].speed_bounds[1]: u^2 = 1 is less than |v(q)|^2 = 2",
     dict(SQUARE_SLIDES, regions=[block(SQUARE_4, speed_bounds=["0", "1", "17/12", "17/12", "17/12"])])),
    ("square_region", "power_below_bound", "invalid:power|twist: power q.p = 9/10 is less than sum mu_i f_i u_i = 17/18",
     dict(SQUARE_SLIDES, load=["0", "0", "9/10"])),
    ("square_region", "without_blocks", 'invalid:keys|missing required key "regions"',
     {k: v for k, v in SQUARE_STICKS.items() if k != "regions"}),
    ("square_frame", "hole_covered", "invalid:tiling|regions[0]: the cells do not tile support.regions[0]",
     dict(FRAME_SLIDES, regions=[block(([[-2, -2], [2, -2], [2, 2], [-2, 2]], [[0, 1, 2], [0, 2, 3]]),
                                       speed_bounds=["1", "1", "1", "1"])])),
    # hold over a region (section 7.4): the pin takes (1, 0); the cells' forces (-3/16, -3/16) at (1/3, -1/3) and
    # (3/16, 3/16) at (-1/3, 1/3) (inside their closed discs of radius 1/2) give the moment -1/4 the load leaves.
    ("square_region_pin_push", "holds", "valid",
     hold(True, combination=comb((0, "normal", "1")), support_forces=[],
          regions=[block(SQUARE_2, forces=[["-3/16", "-3/16"], ["3/16", "3/16"]])])),
    ("square_region_pin_push", "force_outside_disc", "invalid:disc|regions[0].forces[0]: |g|^2 = 45/64 is not at most (mu F)^2 = 1/4",
     hold(True, combination=comb((0, "normal", "1")), support_forces=[],
          regions=[block(SQUARE_2, forces=[["-3/4", "3/8"], ["3/4", "-3/8"]])])),
    ("square_region_pin_push", "without_blocks", 'invalid:keys|missing required key "regions"',
     hold(True, combination=comb((0, "normal", "1")), support_forces=[])),
    # the rotation (0, 0, 1) about the centre: the pin allows it, the region's friction is at most 17/18 (SQUARE_4's
    # bound) < 1 = its power against the load at (0, 1); against the load at (0, 1/4) it is 1/4: no proof.
    ("square_region_pin_turn", "fails", "valid",
     hold(False, twist=["0", "0", "1"], speed_bounds=[],
          regions=[block(SQUARE_4, speed_bounds=["0", "17/12", "17/12", "17/12", "17/12"])])),
    ("square_region_pin_turn", "speed_bound_too_small", "invalid:speed|regions[0].speed_bounds[1]: u^2 = 1 is less than |v(q)|^2 = 2",
     hold(False, twist=["0", "0", "1"], speed_bounds=[],
          regions=[block(SQUARE_4, speed_bounds=["0", "1", "17/12", "17/12", "17/12"])])),
    ("square_region_pin_push", "slide_bound_too_low", "invalid:power|twist: power against the load t.w_L = 1/4 is not more than",
     hold(False, twist=["0", "0", "1"], speed_bounds=[],
          regions=[block(SQUARE_4, speed_bounds=["0", "17/12", "17/12", "17/12", "17/12"])])),
    # hold over a region with forces not given (section 7.5, format 2): each witness carries its regions' blocks.
    # (9/4, 0, 0): at each vertex the legs take 2 (on their circles) and the mat's two cells (-1/8, 0) each (discs of
    # radius 1/4; centroids (1/6, -1/6), (-1/6, 1/6): no moment).
    ("mat_legs_nudged", "holds_for_every", "valid",
     hold2(True, vertices=[dict(hold_witness(["0", "4", "0"], [], [["0", "0"], ["-2", "0"], ["0", "0"]]), regions=[MAT_PUSH]),
                           dict(hold_witness(["2", "0", "2"], [], [["-1", "0"], ["0", "0"], ["-1", "0"]]), regions=[MAT_PUSH])])),
    ("mat_legs_nudged", "vertex_without_regions", 'invalid:keys|vertices[1]: missing required key "regions"',
     hold2(True, vertices=[dict(hold_witness(["0", "4", "0"], [], [["0", "0"], ["-2", "0"], ["0", "0"]]), regions=[MAT_PUSH]),
                           hold_witness(["2", "0", "2"], [], [["-1", "0"], ["0", "0"], ["-1", "0"]])])),
    # the translation (1, 0, 0): mu_i u_i = 1/2 <= y0 = 1/2; the legs resist at most y0 W' = 2, the mat 1/2 (speeds 1):
    # 5/2 < 3. Against (9/4, 0, 0) the same bound is not below the power: without the mat's 1/2 it would be.
    ("mat_legs_shoved", "fails_for_every", "valid",
     hold2(False, twist=["1", "0", "0"], speed_bounds=["1", "1", "1"], regions=[MAT_SLIDE_X], dual=["1/2", "0", "0"])),
    ("mat_legs_nudged", "fails_for_every", "invalid:power|twist: power against the load t.w_L = 9/4 is not more than the dual bound 5/2",
     hold2(False, twist=["1", "0", "0"], speed_bounds=["1", "1", "1"], regions=[MAT_SLIDE_X], dual=["1/2", "0", "0"])),
    # the moment 1: the barbell (2, 0, 2) holds it with (0, 1/4) and (0, -1/4) at its legs; under (0, 4, 0) the middle
    # leg does not move under the rotation (0, 0, 1) and the mat resists at most (1/2)(4 cells)(17/24 + 17/24)/12 = 17/72.
    ("mat_legs_twisted", "depends", "valid",
     hold2("depends", holding=MAT_HOLDING, failing=MAT_FAILING)),
    ("mat_legs_twisted", "format_1", "invalid:regions unknown|holds: a support with regions and points whose force is not given has no certificate in format 1",
     hold("depends", holding=MAT_HOLDING, failing=MAT_FAILING)),
    ("mat_legs_twisted", "holding_outside_F", "invalid:F|holding.distribution: the forces sum to 6 with the regions' 1, not the weight 5",
     hold2("depends", holding=dict(MAT_HOLDING, distribution=["5/2", "0", "5/2"]), failing=MAT_FAILING)),
    # motion over the mat and legs (section 6.5, format 2)
    ("mat_legs", "motion_sticks_for_every", "valid", motion2("sticks", [2, 0, 0], vertices=MAT_STICKS)),
    ("mat_legs", "motion_vertex_without_regions", 'invalid:keys|vertices[1]: missing required key "regions"',
     motion2("sticks", [2, 0, 0], vertices=[MAT_STICKS[0], stick_witness(["2", "0", "2"], [["1", "0"], ["0", "0"], ["1", "0"]])])),
    ("mat_legs", "motion_vertex_missing", "invalid:vertex|vertices: the vertex (2, 0, 2) of the admissible distributions has no witness",
     motion2("sticks", [2, 0, 0], vertices=MAT_STICKS[:1])),
    ("mat_legs", "motion_cell_on_its_circle", "invalid:stick|vertices[0].regions[0].forces[0]: |g|^2 = 1/16 is not less than (mu F)^2 = 1/16",
     motion2("sticks", [2, 0, 0], vertices=[dict(MAT_STICKS[0], support_forces=[["0", "0"], ["3/2", "0"], ["0", "0"]],
                                                 regions=[block(MAT_2, forces=[["1/4", "0"], ["1/4", "0"]])]), MAT_STICKS[1]])),
    # (3, 0, 0) slides for every distribution: the translation (1, 0, 0), mu_i u_i = 1/2 <= y0 = 1/2, the legs resist at
    # most y0 W' = 2 and the mat 1/2; (5/2, 0, 0) meets that bound exactly (on every limit surface: slides); (2, 0, 0) not.
    ("mat_legs", "motion_slides_for_every", "valid",
     motion2("slides", [3, 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1", "1"], dual=["1/2", "0", "0"], regions=[MAT_SLIDE_X])),
    ("mat_legs", "motion_slides_on_the_boundary", "valid",
     motion2("slides", [F(5, 2), 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1", "1"], dual=["1/2", "0", "0"],
             regions=[MAT_SLIDE_X])),
    ("mat_legs", "motion_slides_below_the_bound", "invalid:power|twist: power q.p = 2 is less than the dual bound 5/2",
     motion2("slides", [2, 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1", "1"], dual=["1/2", "0", "0"], regions=[MAT_SLIDE_X])),
    ("mat_legs", "motion_slides_without_the_mat", 'invalid:keys|missing required key "regions"',
     motion2("slides", [3, 0, 0], twist=["1", "0", "0"], speed_bounds=["1", "1", "1"], dual=["1/2", "0", "0"])),
    ("mat_legs", "motion_depends", "valid", motion2("depends", [0, 0, 1], sticking=MAT_STICKING, sliding=MAT_FAILING)),
    ("mat_legs", "motion_format_1", "invalid:regions unknown|motion: a support with regions and points whose force is not given has no certificate in format 1",
     motion("depends", [0, 0, 1], sticking=MAT_STICKING, sliding=MAT_FAILING)),
    ("mat_legs", "motion_regions_at_the_top", 'invalid:keys|key "regions" is not allowed when "motion" is "depends" at the top level',
     motion2("depends", [0, 0, 1], sticking=MAT_STICKING, sliding=MAT_FAILING, regions=[block(MAT_2, forces=[["0", "0"], ["0", "0"]])])),
    ("mat_legs", "motion_sliding_outside_F", "invalid:F|sliding.distribution: the forces sum to 6 with the regions' 1, not the weight 5",
     motion2("depends", [0, 0, 1], sticking=MAT_STICKING, sliding=dict(MAT_FAILING, distribution=["0", "5", "0"]))),
    ("mat_legs_twisted", "regions_at_the_top", 'invalid:keys|key "regions" is not allowed when "holds" is "depends" at the top level',
     hold2("depends", holding=MAT_HOLDING, failing=MAT_FAILING, regions=[block(MAT_2, forces=[["0", "0"], ["0", "0"]])])),
    ("barbell_known", "blocks_without_regions", 'invalid:keys|key "regions" is not allowed when "motion" is "sticks" and the support has no regions',
     motion("sticks", [F(1, 4), 0, 0], support_forces=[["1/8", "0"], ["1/8", "0"]], regions=[])),

    # pushing (certificate-format.md section 8, format 6)
    ("push_square", "ccw", "valid", PUSH_SQUARE),
    ("push_square", "locus", "valid", LOCUS_SQUARE),
    ("push_contact_depends", "depends", "valid", CONTACT_DEPENDS),
    ("push_contact_depends", "witness_not_in_f", "invalid:F|contact.witnesses[0].forces: the forces sum to 3, not the weight 4",
     tamper(CONTACT_DEPENDS, ["contact", "witnesses", 0, "forces"], ["1", "0", "2", "0", "0"])),
    ("push_contact_depends", "witnesses_alike", 'invalid:contact|contact.witnesses: "depends" needs two distributions whose contact modes differ',
     tamper(CONTACT_DEPENDS, ["contact", "witnesses", 1], CONTACT_DEPENDS["contact"]["witnesses"][0])),
    ("push_square", "locus_polygon_cut", "invalid:polygon|locus.ccw[1].polygon: the vertex (1/2, 5/2) of the centres' bound is outside it",
     tamper(LOCUS_SQUARE, ["locus", "ccw", 1, "polygon", 3], ["1/2", "2"])),
    ("push_square", "locus_arm_short", "invalid:arm|locus.arm_hi: 3 is below a possible centre's distance",
     tamper(LOCUS_SQUARE, ["locus", "arm_hi"], "3")),
    ("push_square", "locus_sense_dropped", 'invalid:sense|locus.ccw: null, but the rotation "ccw" does not exclude this sense',
     dict(LOCUS_SQUARE, locus=dict(LOCUS_SQUARE["locus"], ccw=None, cw=LOCUS_SQUARE["locus"]["ccw"]))),
    ("push_square", "locus_tip_too_close", "invalid:locus|locus.T: 2 is below R^2 + E(T/alpha_hi)",
     tamper(LOCUS_SQUARE, ["locus", "T"], "2")),
    ("push_square_unknown", "locus", "valid", LOCUS_UNKNOWN),
    ("push_square_unknown", "locus_without_tip_line", "invalid:unbounded|locus.ccw[0]: claimed bounded, but its half-planes recede",
     tamper(tamper(LOCUS_UNKNOWN, ["locus", "T"], None), ["locus", "alpha_hi"], None)),
    ("push_slide", "locus_translates", "valid", LOCUS_TRANSLATES),
    ("push_square_unknown", "locus_slowest", "valid", LOCUS_SLOWEST),
    ("push_square_unknown", "locus_arm_lo_too_far", "invalid:arm|locus.arm_lo: 6 is more than v.n / (|omega| |n|)",
     tamper(LOCUS_SLOWEST, ["locus", "arm_lo"], "6")),
    ("push_square", "wrong_rotation", 'invalid:rotation|rotation: "cw", but votes cw/ccw/ccw (left edge, right edge, velocity; "none" = through c) allowed by the bounds give "ccw"',
     tamper(PUSH_SQUARE, ["rotation"], "cw")),
    ("push_square", "short_bound", "invalid:bound|votes[2].upper: 2 is less than the proven 3",
     tamper(PUSH_SQUARE, ["votes", 2, "upper"], "2")),
    # sound but loose: the velocity's range [-1, 3] allows every sign, and with the edges apart so does the rule
    ("push_square", "loose_bounds", 'invalid:rotation|rotation: "ccw", but votes cw/ccw/cw (left edge, right edge, velocity; "none" = through c) allowed by the bounds give "cw"',
     tamper(PUSH_SQUARE, ["votes", 2, "lower"], "-1")),
    ("push_square", "wrong_center", "invalid:center|center: (1/2, 0) is not the centre of friction (0, 0)",
     tamper(PUSH_SQUARE, ["center"], ["1/2", "0"])),
    ("push_square", "in_format_5", 'invalid:header|wrenchkit_certificate: property "push" is format 6 (expected the integer 6)',
     tamper(PUSH_SQUARE, ["wrenchkit_certificate"], 5)),
    ("push_depends", "depends", "valid", PUSH_DEPENDS),
    # (1, 1, 0, 0) would turn the body ccw as well, but it carries 2, not the weight 4
    ("push_depends", "not_in_f", "invalid:F|turns.ccw: the forces sum to 2, not the weight 4",
     tamper(PUSH_DEPENDS, ["turns", "ccw"], ["1", "1", "0", "0"])),
    ("push_depends", "same_way", "invalid:turns|turns.cw: its votes do not turn the body cw",
     tamper(PUSH_DEPENDS, ["turns", "cw"], ["2", "2", "0", "0"])),
    ("push_depends", "center_moves", "invalid:center|center: the support's coefficients differ and some force is not given",
     tamper(PUSH_DEPENDS, ["center"], ["0", "0"])),
    ("push_square_unknown", "ccw", "valid", PUSH_UNKNOWN),
    ("push_square_unknown", "weak_dual", "invalid:bound|friction.lower: 2 is more than the proven 1",
     tamper(PUSH_UNKNOWN, ["friction", "dual_lower"], ["-1/4", "0", "0"])),
    ("push_square_unknown", "dual_violated", "invalid:dual|votes[2].dual_lower: -coef_i = -3/4 is more than y0 + yx x_i + yy y_i = -7/4 at support.points[0]",
     tamper(PUSH_UNKNOWN, ["votes", 2, "dual_lower"], ["-1/4", "1/2", "1"])),
    ("push_square_unknown", "without_dual", "invalid:dual|votes[1]: some support force is not given, so each bound needs its LP dual over F",
     tamper(PUSH_UNKNOWN, ["votes", 1, "dual_upper"], None)),
    ("push_square_centre", "none", "valid", PUSH_CENTRE),
    ("push_square", "contact_sticks", "valid", PUSH_SQUARE_CONTACT),
    ("push_square", "contact_sticks_bracket_moved", "invalid:contact|contact.omega: the moment about the pusher at omega",
     tamper(PUSH_SQUARE_CONTACT, ["contact", "omega", 0], "603540960162815/1125899906842624")),
    ("push_square", "contact_claims_slide", "invalid:contact|contact: a sliding claim needs \"tangent_omega\"",
     tamper(PUSH_SQUARE_CONTACT, ["contact", "mode"], "slides right")),
    ("push_slide", "contact_slides_left", "valid", PUSH_SLIDE),
    ("push_slide", "contact_slides_right", "invalid:contact|contact: \"slides right\", but the sticking motion's force is not certainly beyond",
     tamper(PUSH_SLIDE, ["contact", "mode"], "slides right")),
    ("push_slide", "contact_sticks", "invalid:contact|contact: \"sticks\", but the sticking motion's force is not certainly inside",
     tamper(tamper(PUSH_SLIDE, ["contact", "mode"], "sticks"), ["contact", "sliding"], None)),
    ("push_slide", "contact_exact_slip_moved", "invalid:contact|contact.sliding: an exact slip is only the translation along the edge through",
     tamper(PUSH_SLIDE, ["contact", "sliding", "slip"], ["-1/4", "-1/4"])),
    ("push_slide_right", "contact_slides_right", "valid", PUSH_SLIDE_RIGHT),
    ("push_stick_pivot", "contact_stick_pivot", "valid", PUSH_STICK_PIVOT),
    ("push_stick_pivot", "contact_stick_pivot_rate_moved", "invalid:contact|contact.omega: the rotation about the pivot has omega 1",
     tamper(PUSH_STICK_PIVOT, ["contact", "omega"], ["2", "2"])),
    ("push_stick_pivot", "contact_stick_pivot_not_perpendicular", "invalid:contact|contact.pivot: the pusher's velocity is not perpendicular",
     tamper(PUSH_STICK_PIVOT, ["contact", "pivot"], 1)),
    ("push_stick_pivot", "contact_stick_pivot_force_outside", "invalid:contact|contact.force: not strictly inside the friction cone",
     tamper(PUSH_STICK_PIVOT, ["contact", "force"], ["1", "0"])),
    ("push_stick_pivot", "contact_stick_pivot_facet_misses", "invalid:contact|contact.pivot: no force of the pivot's facet is certainly along",
     tamper(PUSH_STICK_PIVOT, ["contact", "force"], ["1", "5"])),
    ("push_fence", "stable_translating", "valid", FENCE_STABLE),
    ("push_fence", "claims_a_turn", "invalid:rotation|rotation: a stable push turns with the pusher",
     tamper(FENCE_STABLE, ["rotation"], "ccw")),
    ("push_fence_slanted", "unstable_translating", "valid", FENCE_SLANTED),
    ("push_fence_slanted", "claims_stable", "invalid:facet|stable: the load is beyond the composite cone's right edge",
     tamper(tamper(tamper(FENCE_SLANTED, ["stable", "verdict"], "stable"), ["stable", "facet"], None), ["rotation"], "none")),
    ("push_fence_turning", "stable_tip_line", "valid", FENCE_TURNING),
    ("push_fence_turning", "tip_bound_too_high", "invalid:bound|stable.d_lo: not a lower bound of |q - c|",
     tamper(FENCE_TURNING, ["stable", "d_lo"], "11")),
    ("push_fence_turning", "stable_region", "valid", FENCE_REGION),
    ("push_fence_turning", "region_tip_too_close", "invalid:region|region.ccw.T: 29/10 is below R^2 + E(T/alpha_hi)",
     tamper(FENCE_REGION, ["region", "ccw", "T"], "29/10")),
    ("push_fence_turning", "region_translation_outside", "invalid:region|region.translations[0]: (1, 1) is not a stable translation",
     tamper(FENCE_REGION, ["region", "translations"], [["1", "1"], ["-1/2", "1"]])),
    ("push_fence_aside", "unstable_turns_ccw", "valid", FENCE_ASIDE),
    ("push_fence_aside", "claims_cw", "invalid:rotation|rotation: an unstable push's rotation needs every force",
     tamper(FENCE_ASIDE, ["rotation"], "cw")),
    ("push_fence_near", "stable_by_dual", "valid", FENCE_NEAR),
    ("push_fence_near", "dual_not_negative", "invalid:dual|stable.duals.end 1: y0 is not negative",
     tamper(FENCE_NEAR, ["stable", "duals", "end 1"], ["1/1000000", "210017/250000", "132551/500000"])),
    ("push_fence_close", "unstable_witness", "valid", FENCE_CLOSE),
    ("push_fence_close", "witness_off_centre", "invalid:witness|stable.witness: its mean is not the centre of friction",
     tamper(FENCE_CLOSE, ["stable", "witness", "weights"], ["1", "2"])),
    ("push_fence_close", "witness_wrong_facet", "invalid:witness|stable.witness: its load is not certainly beyond the composite cone's right edge",
     tamper(FENCE_CLOSE, ["stable", "facet"], "right edge")),
    ("push_slide_pivot", "contact_slides_from_pivot", "valid", PUSH_SLIDE_PIVOT),
    ("push_slide_pivot", "contact_slides_left_from_pivot", "invalid:contact|contact.pivot: not every force of the pivot's facet through the pusher is certainly beyond the claimed edge",
     tamper(PUSH_SLIDE_PIVOT, ["contact", "mode"], "slides left")),
    ("push_slide_pivot", "contact_slide_pivot_with_force", "invalid:contact|\"force\" is a sticking pivot's",
     tamper(PUSH_SLIDE_PIVOT, ["contact", "force"], ["1", "5"])),
    ("push_stick_pivot", "contact_slides_from_a_sticking_pivot", "invalid:contact|contact.pivot: not every force of the pivot's facet through the pusher is certainly beyond",
     tamper(tamper(PUSH_SLIDE_PIVOT, ["contact", "sliding"], None), ["votes"], PUSH_STICK_PIVOT["votes"])),
    ("push_tangent_pivot", "contact_tangent_pivot", "valid", PUSH_TANGENT_PIVOT),
    ("push_tangent_pivot", "contact_tangent_pivot_moved", "invalid:contact|contact.tangent_pivot: the tangent rot90(n) is not perpendicular",
     tamper(PUSH_TANGENT_PIVOT, ["contact", "tangent_pivot"], 1)),
    ("push_tangent_pivot", "contact_tangent_pivot_rate_moved", "invalid:contact|contact.tangent_omega: the rotation about the pivot has omega -1",
     tamper(PUSH_TANGENT_PIVOT, ["contact", "tangent_omega"], ["-2", "-2"])),
    ("push_pivot", "contact_pivot", "valid", PUSH_PIVOT),
    ("push_pivot", "contact_other_pivot", "invalid:contact|contact.sliding: the rotation about the pivot has slip",
     tamper(PUSH_PIVOT, ["contact", "sliding", "pivot"], 1)),
    ("push_pivot", "contact_facet_misses_the_edge", "invalid:contact|contact.sliding.pivot: no force of the pivot's facet is certainly along the edge",
     tamper(PUSH_PIVOT, ["contact", "sliding"], {"pivot": 1, "slip": ["23/31", "23/31"], "omega": ["-6/31", "-6/31"]})),
    ("push_pivot", "contact_pivot_rate_moved", "invalid:contact|contact.sliding: the rotation about the pivot has slip 5/7 and omega -3/7",
     tamper(PUSH_PIVOT, ["contact", "sliding", "omega"], ["-1/2", "-1/2"])),
    ("push_slide_right", "contact_rate_bracket_moved", "invalid:contact|contact.sliding.omega: the moment about the pusher at omega",
     tamper(PUSH_SLIDE_RIGHT, ["contact", "sliding", "omega", 0], "7669685355580945/18014398509481984")),
    ("push_slide_right", "contact_slip_reversed", "invalid:contact|contact.sliding: \"slip\" and \"omega\" are intervals",
     tamper(PUSH_SLIDE_RIGHT, ["contact", "sliding", "slip"], ["5737413245659969/18014398509481984", "5737404238460715/18014398509481984"])),
    ("push_square", "contact_sliding_on_sticks", "invalid:contact|contact.sliding: only a sliding contact has a sliding motion",
     tamper(PUSH_SQUARE_CONTACT, ["contact", "sliding"], PUSH_SLIDE_RIGHT["contact"]["sliding"])),
    # the same tie on the barbell (D = 1; the velocity's N = 1): the engine answers "undecided" and writes nothing
    ("push_barbell", "none_on_a_line", "invalid:line|the support's friction lies on one line through the centre of friction",
     json.loads(r'''{"wrenchkit_certificate": 6, "property": "push", "rotation": "none", "friction": {"lower": "1"}, "votes": [{"lower": "0", "upper": "0"}, {"lower": "0", "upper": "0"}, {"lower": "1", "upper": "1"}], "center": ["0", "0"]}''')),
]

# ----------------------------------------------------------------------------------------------
# An independent exact checker (Python fractions)

PROPERTIES = ("force_closure", "form_closure", "equilibrium", "motion", "hold")
SCENE_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?|[+-]?\d+/\d+")
RATIONAL = re.compile(r"-?(0|[1-9][0-9]*)(/[1-9][0-9]*)?")


def number(x):
    text = x if isinstance(x, str) else str(x)
    assert SCENE_NUMBER.fullmatch(text), text
    return F(text)  # Fraction reads decimals, exponents and p/q exactly


def generators(contact, friction):
    if "wrench" in contact:
        return {"wrench": tuple(number(v) for v in contact["wrench"])}
    (px, py), (nx, ny) = (number(v) for v in contact["at"]), (number(v) for v in contact["normal"])
    mu = number(contact.get("mu", 0))

    def W(fx, fy):
        return (fx, fy, px * fy - py * fx)

    if not friction or mu == 0:
        return {"normal": W(nx, ny)}
    return {"left": W(nx - mu * ny, ny + mu * nx), "right": W(nx + mu * ny, ny - mu * nx)}


def load_wrench(scene):
    """w_ext of the scene's load (certificate-format.md section 3.3), or None without a load."""
    load = scene.get("load")
    if load is None:
        return None
    if set(load) == {"gravity"}:
        w, (cx, _) = number(load["gravity"]), (number(v) for v in scene["body"]["com"])
        assert w > 0
        return (F(0), -w, -w * cx)
    if set(load) == {"wrench"}:
        return tuple(number(v) for v in load["wrench"])
    assert set(load) == {"force", "at"}, load
    (fx, fy), (x, y) = (number(v) for v in load["force"]), (number(v) for v in load["at"])
    return (fx, fy, x * fy - y * fx)


def rational(s):
    if not isinstance(s, str) or not RATIONAL.fullmatch(s):
        raise ValueError(f"{s!r} is not a rational")
    return F(s)


def det3(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


MOTION_KEYS = {  # (claim, every force given) -> the keys besides the common ones
    ("sticks", True): {"support_forces"}, ("slides", True): {"twist", "speed_bounds"},
    ("sticks", False): {"vertices"}, ("slides", False): {"twist", "speed_bounds", "dual"},
    ("depends", False): {"sticking", "sliding"},
    ("impending", True): {"support_forces", "twist", "speed_bounds"},
    ("impending", False): {"vertices", "twist", "speed_bounds", "dual"},
}


def gauss_solve(columns, b):
    """The unique x with sum_j x_j columns[j] = b if the columns are independent and b is in their span,
    else None (Gauss-Jordan elimination on Fractions; a second method beside the C++ checker's Cramer rule)."""
    n = len(columns)
    A = [[columns[j][k] for j in range(n)] + [b[k]] for k in range(3)]
    row = 0
    for col in range(n):
        piv = next((r for r in range(row, 3) if A[r][col] != 0), None)
        if piv is None:
            return None  # dependent columns
        A[row], A[piv] = A[piv], A[row]
        A[row] = [v / A[row][col] for v in A[row]]
        for r in range(3):
            if r != row:
                A[r] = [a - A[r][col] * c for a, c in zip(A[r], A[row])]
        row += 1
    if any(A[r][n] != 0 for r in range(n, 3)):
        return None
    return [A[r][n] for r in range(n)]


def vertices_of_F(pts, given, W, c, regions=()):
    """The vertices of F by brute force: every set S of at most three unknown points whose columns (1, x, y) are
    independent and give a strictly positive solution of the three rows (and the given forces alone when the rest
    is zero)."""
    unknown = [i for i, q in enumerate(pts) if q[3] is None]
    b = ([W - sum(given) - sum(r["W"] for r in regions)]
         + [W * c[k] - sum(f * q[k] for f, q in zip(given, pts)) - sum(r["M"][k] for r in regions) for k in range(2)])
    out = []
    for size in range(0, 4):
        for S in itertools.combinations(unknown, size):
            x = [] if size == 0 else gauss_solve([(F(1), pts[i][0], pts[i][1]) for i in S], b)
            if (size == 0 and any(b)) or x is None or any(v <= 0 for v in x):
                continue
            f = list(given)
            for i, v in zip(S, x):
                f[i] = v
            out.append(f)
    return out


def region(r, sup):
    """A support region, oriented (outline counter-clockwise, holes clockwise), with its pressure, mu and W
    (the examples' regions are valid; their validity is the C++ checker's and the readers' business)."""
    def area2(ring):
        return sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(ring, ring[1:] + ring[:1]))
    rings = []
    for k, ring in enumerate([r["outline"]] + r.get("holes", [])):
        ring = [(number(x), number(y)) for x, y in ring]
        if (area2(ring) > 0) != (k == 0):
            ring = ring[::-1]
        rings.append(ring)
    area = sum(area2(ring) for ring in rings) / 2
    coef = [number(r["force"]) / area, F(0), F(0)] if r["pressure"] == "uniform" else [number(v) for v in r["pressure"]["linear"]]
    reg = {"rings": rings, "coef": coef, "mu": number(r.get("mu", sup.get("mu")))}
    # W by the fan triangles (0, a, b) of the oriented boundary, the edge-midpoint rule on each.
    def fan(g):  # the integral of g(r) p(r) over the region, by the fan triangles' edge midpoints (degree <= 2)
        return sum((a[0] * b[1] - a[1] * b[0]) / 2 / 3 * sum(g(m) * pressure(reg, m) for m in (
            (a[0] / 2, a[1] / 2), (b[0] / 2, b[1] / 2), ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)))
            for ring in rings for a, b in zip(ring, ring[1:] + ring[:1]))
    reg["W"] = fan(lambda m: 1)
    reg["M"] = (fan(lambda m: m[0]), fan(lambda m: m[1]))
    return reg


def pressure(reg, v):
    c = reg["coef"]
    return c[0] + c[1] * v[0] + c[2] * v[1]


def cells_of(blk):
    return [(rational(x), rational(y)) for x, y in blk["vertices"]], blk["triangles"]


def cell_measures(reg, tri):
    """F = integral of p over the cell, and the integral of r p (edge-midpoint rule, exact for degree 2)."""
    a, b, c = tri
    area = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2
    mids = [((u[0] + v[0]) / 2, (u[1] + v[1]) / 2) for u, v in ((a, b), (b, c), (c, a))]
    return (area / 3 * sum(pressure(reg, m) for m in mids),
            (area / 3 * sum(m[0] * pressure(reg, m) for m in mids), area / 3 * sum(m[1] * pressure(reg, m) for m in mids)))


def tiles(reg, vs, tris):
    """The cells tile the region: every cell counter-clockwise with positive area, and on every line the cells'
    oriented edges minus the region's cancel (a second implementation: unit steps summed on a common grid of the
    line's end points)."""
    segments = []
    for t in tris:
        if len(t) != 3 or any(type(i) is not int or not 0 <= i < len(vs) for i in t):
            return False
        a, b, c = (vs[i] for i in t)
        if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0:
            return False
        segments += [(a, b, 1), (b, c, 1), (c, a, 1)]
    for ring in reg["rings"]:
        segments += [(a, b, -1) for a, b in zip(ring, ring[1:] + ring[:1])]
    lines = {}
    for p, q, w in segments:
        if p[0] != q[0]:
            s = (q[1] - p[1]) / (q[0] - p[0])
            key, t0, t1 = ("slope", s, p[1] - s * p[0]), p[0], q[0]
        else:
            key, t0, t1 = ("vertical", p[0]), p[1], q[1]
        lines.setdefault(key, []).append((t0, t1, w))
    for pieces in lines.values():
        grid = sorted({t for t0, t1, _ in pieces for t in (t0, t1)})
        for lo, hi in zip(grid, grid[1:]):
            mid = (lo + hi) / 2
            if sum(w if t0 < mid < t1 else -w if t1 < mid < t0 else 0 for t0, t1, w in pieces) != 0:
                return False
    return True


def slide_block_bound(reg, blk, q):
    """A slide block's bound mu sum_cells sum_j w_j u_j at the twist q, or None if a speed bound is too small."""
    vs, tris = cells_of(blk)
    ub = [rational(v) for v in blk["speed_bounds"]]
    if len(ub) != len(vs) or any(v < 0 or v * v < (q[0] - q[2] * y) ** 2 + (q[1] + q[2] * x) ** 2
                                 for v, (x, y) in zip(ub, vs)):
        return None
    bound = F(0)
    for tri in tris:
        a, b, c3 = (vs[i] for i in tri)
        area = ((b[0] - a[0]) * (c3[1] - a[1]) - (b[1] - a[1]) * (c3[0] - a[0])) / 2
        pv = [pressure(reg, v) for v in (a, b, c3)]
        bound += reg["mu"] * area * sum((pj + sum(pv)) * ub[i] for pj, i in zip(pv, tri)) / 12
    return bound


def witness_blocks(witnesses, regions, per_witness):
    """Format 2 (sections 6.5 and 7.5): each witness carries one block per region exactly when per_witness, and
    each block's cells tile its region. The reason it fails ("keys", "tiling"), or None."""
    for w in witnesses:
        if ("regions" in w) != per_witness or (per_witness and len(w["regions"]) != len(regions)):
            return "keys"
        for reg, blk in zip(regions, w.get("regions", ())):
            if not tiles(reg, *cells_of(blk)):
                return "tiling"
    return None


def verify_motion(scene, cert):
    """verify() for property "motion": None if valid, else a short reason."""
    sup = scene.get("support")
    if sup is None:
        return "no support"
    pts = [(number(q["at"][0]), number(q["at"][1]), number(q.get("mu", sup.get("mu"))),
            None if "force" not in q else number(q["force"])) for q in sup.get("points", [])]
    regions = [region(r, sup) for r in sup.get("regions", [])]
    known = all(f is not None for *_, f in pts)
    claim = cert["motion"]
    v3 = cert["wrenchkit_certificate"] >= 3  # section 6.6: "impending" names the surface; "slides" is strict
    if claim == "impending" and not v3:
        return "version"
    if claim == "depends" and known:
        return "depends known"
    per_witness = bool(regions) and not known  # format 2 (section 6.5): each witness carries its regions' blocks
    if per_witness and cert["wrenchkit_certificate"] < 2:
        return "regions unknown"
    top = bool(regions) and (known or claim in ("slides", "impending"))
    if set(cert) != {"wrenchkit_certificate", "property", "load", "motion"} | MOTION_KEYS[(claim, known)] | (
            {"regions"} if top else set()):
        return "keys"
    if top and len(cert["regions"]) != len(regions):
        return "keys"
    bad = witness_blocks([cert["sticking"], cert["sliding"]] if claim == "depends" else cert.get("vertices", []),
                         regions, per_witness)
    if bad:
        return bad
    p = [rational(v) for v in cert["load"]]
    given = [f or F(0) for *_, f in pts]
    fixed = (sum(r["W"] for r in regions), [sum(r["M"][k] for r in regions) for k in range(2)])  # a known pressure
    if known:
        W, c = sum(given) + fixed[0], None
    else:
        W = number(sup["weight"])
        c = [number(v) for v in sup.get("pressure_center", scene.get("body", {}).get("com"))]

    def in_F(f):
        return (len(f) == len(pts) and all(v >= 0 for v in f)
                and all(q[3] is None or q[3] == v for q, v in zip(pts, f)) and sum(f) + fixed[0] == W
                and all(sum(v * q[k] for v, q in zip(f, pts)) + fixed[1][k] == W * c[k] for k in range(2)))

    def region_bound(q, blocks):  # sum_R mu_R sum_cells sum_j w_j u_j, or a reason
        bound = 0
        for reg, blk in zip(regions, blocks):
            if not tiles(reg, *cells_of(blk)):
                return "tiling"
            b = slide_block_bound(reg, blk, q)
            if b is None:
                return "speed"
            bound += b
        return bound

    def sticks(f, g, blocks=(), strict=True):  # strict: p in the interior of LS(f), open discs at two places;
        g = [[rational(a) for a in gi] for gi in g]  # else p in the closed LS(f)
        if len(g) != len(pts) or any(a * a + b * b > (q[2] * fi) ** 2 or (strict and q[2] * fi != 0 and
                                                                          a * a + b * b == (q[2] * fi) ** 2)
                                     for (a, b), q, fi in zip(g, pts, f)):
            return False
        places = {(q[0], q[1]) for q, fi in zip(pts, f) if q[2] * fi > 0}
        total = [sum(a for a, _ in g), sum(b for _, b in g), sum(q[0] * b - q[1] * a for (a, b), q in zip(g, pts))]
        for reg, blk in zip(regions, blocks):  # each cell's force acts at its pressure centroid
            vs, tris = cells_of(blk)
            if not tiles(reg, vs, tris) or len(blk["forces"]) != len(tris):
                return False
            for t, (a, b) in zip(tris, ([rational(x) for x in gk] for gk in blk["forces"])):
                Fk, (mx, my) = cell_measures(reg, [vs[i] for i in t])
                rho = reg["mu"] * Fk
                if a * a + b * b > rho * rho or (strict and rho != 0 and a * a + b * b == rho * rho):
                    return False
                if rho > 0:
                    places.add((mx / Fk, my / Fk))
                    total = [total[0] + a, total[1] + b, total[2] + (mx * b - my * a) / Fk]
        return (len(places) >= 2 or not strict) and total == p

    def speeds(q, u):  # None if fine, else the reason
        if not any(q):
            return "zero twist"
        if len(u) != len(pts) or any(v < 0 for v in u):
            return "speed"
        if any(v * v < (q[0] - q[2] * y) ** 2 + (q[1] + q[2] * x) ** 2 for v, (x, y, *_) in zip(u, pts)):
            return "speed"
        return None

    def power(q):  # q.p; a slide witness needs q != 0 and q.p >= the bound (a load on the limit surface slides)
        return q[0] * p[0] + q[1] * p[1] + q[2] * p[2]

    def beats(power_, bound_, strict):  # slides in format 3: strictly; impending (and formats 1, 2): at least
        return power_ > bound_ if strict else power_ >= bound_

    if claim in ("sticks", "impending") and known:
        if regions and any(not tiles(reg, *cells_of(blk)) for reg, blk in zip(regions, cert["regions"])):
            return "tiling"
        if not sticks(given, cert["support_forces"], cert.get("regions", ()), claim == "sticks"):
            return "stick"
        if claim == "sticks":
            return None
    if claim in ("slides", "impending"):
        strict = v3 and claim == "slides"
        if claim == "impending" and not known:  # every vertex of F in its closed set, then the twist over F
            wit = []
            for w in cert["vertices"]:
                f = [rational(v) for v in w["distribution"]]
                if not in_F(f):
                    return "F"
                if not sticks(f, w["support_forces"], w.get("regions", ()), False):
                    return "stick"
                wit.append(f)
            if not all(f in wit for f in vertices_of_F(pts, given, W, c, regions)):
                return "vertex"
        q, u = [rational(v) for v in cert["twist"]], [rational(v) for v in cert["speed_bounds"]]
        if speeds(q, u):
            return speeds(q, u)
        rb = region_bound(q, cert.get("regions", ()))  # mu sum_cells sum_j w_j u_j per region
        if isinstance(rb, str):
            return rb
        if known:
            bound = sum(qq[2] * f * v for qq, f, v in zip(pts, given, u)) + rb
            return None if beats(power(q), bound, strict) else "power"
        y = [rational(v) for v in cert["dual"]]
        if any(q_[3] is None and q_[2] * v > y[0] + y[1] * q_[0] + y[2] * q_[1] for q_, v in zip(pts, u)):
            return "dual"
        rest_w = W - sum(given) - fixed[0]
        rest_m = [W * c[k] - sum(f * q_[k] for f, q_ in zip(given, pts)) - fixed[1][k] for k in range(2)]
        bound = (sum(q_[2] * f * v for q_, f, v in zip(pts, given, u) if q_[3] is not None)
                 + y[0] * rest_w + y[1] * rest_m[0] + y[2] * rest_m[1] + rb)
        return None if beats(power(q), bound, strict) else "power"
    if claim == "depends":
        st, sl = cert["sticking"], cert["sliding"]
        f1, f2 = [rational(v) for v in st["distribution"]], [rational(v) for v in sl["distribution"]]
        if not in_F(f1) or not in_F(f2):
            return "F"
        if not sticks(f1, st["support_forces"], st.get("regions", ()), not v3):
            return "stick"
        q, u = [rational(v) for v in sl["twist"]], [rational(v) for v in sl["speed_bounds"]]
        if speeds(q, u):
            return speeds(q, u)
        rb = region_bound(q, sl.get("regions", ()))
        if isinstance(rb, str):
            return rb
        bound = sum(qq[2] * f * v for qq, f, v in zip(pts, f2, u)) + rb
        if power(q) < bound:
            return "power"
        # Format 3: the two witnesses closed and at least; one strict (else both are on the surface: impending).
        return None if not v3 or power(q) > bound or sticks(f1, st["support_forces"], st.get("regions", ())) else "strict"
    # sticks for every distribution: every witness in F and sticking, every vertex of F witnessed.
    # Vertices by brute force: every set S of at most three unknown points whose columns (1, x, y) are
    # independent and give a strictly positive solution of the three rows.
    wit = []
    for w in cert["vertices"]:
        f = [rational(v) for v in w["distribution"]]
        if not in_F(f):
            return "F"
        if not sticks(f, w["support_forces"], w.get("regions", ())):
            return "stick"
        wit.append(f)
    return None if all(f in wit for f in vertices_of_F(pts, given, W, c, regions)) else "vertex"


def verify_hold(scene, cert):
    """verify() for property "hold" (section 7): None if valid, else a short reason. Independent of verify_motion:
    closed discs, contact weights, strict power, the vertices of F by brute force."""
    load = load_wrench(scene)
    if load is None:
        return "no load"
    gens = [generators(c, True) for c in scene.get("contacts", [])]
    sup = scene.get("support")
    pts = [] if sup is None else [
        (number(q["at"][0]), number(q["at"][1]), number(q.get("mu", sup.get("mu"))),
         None if "force" not in q else number(q["force"])) for q in sup.get("points", [])]
    known = all(f is not None for *_, f in pts)
    regions = [] if sup is None else [region(r, sup) for r in sup.get("regions", [])]
    claim = cert["holds"]
    v3 = cert["wrenchkit_certificate"] >= 3  # section 7.6: true is held with margin; the boundary is "impending"
    if claim == "impending" and not v3:
        return "version"
    if claim == "depends" and known:
        return "depends known"
    per_witness = bool(regions) and not known  # format 2 (section 7.5): each witness carries its regions' blocks
    if per_witness and cert["wrenchkit_certificate"] < 2:
        return "regions unknown"
    top = regions and (known or claim is False or claim == "impending")
    base = {"wrenchkit_certificate", "property", "holds"} | ({"regions"} if top else set())
    bad = witness_blocks([cert["holding"], cert["failing"]] if claim == "depends" else cert.get("vertices", []),
                         regions, per_witness)
    if bad:
        return bad
    held = ({"combination"} | ({"support_forces"} if sup else set())) if known else {"vertices"}
    moved = {"twist"} | ({"speed_bounds"} if sup else set()) | (set() if known else {"dual"})
    want = held if claim is True else moved if claim is False else held | moved if claim == "impending" else {
        "holding", "failing"}
    if set(cert) - {"reading"} != base | want or ("reading" in cert and claim not in (False, "impending")):
        return "keys"
    if top and len(cert["regions"]) != len(regions):
        return "keys"
    for reg, blk in zip(regions, cert.get("regions", ())):
        if not tiles(reg, *cells_of(blk)):
            return "tiling"
    given = [f or F(0) for *_, f in pts]
    fixed = (sum(r["W"] for r in regions), [sum(r["M"][k] for r in regions) for k in range(2)])  # a known pressure
    if sup is not None and not known:
        W, c = number(sup["weight"]), [number(v) for v in sup.get("pressure_center", scene.get("body", {}).get("com"))]
    else:
        W, c = sum(given), None

    def in_F(f):
        return (len(f) == len(pts) and all(v >= 0 for v in f) and all(q[3] is None or q[3] == v for q, v in zip(pts, f))
                and sum(f) + fixed[0] == W
                and all(sum(v * q[k] for v, q in zip(f, pts)) + fixed[1][k] == W * c[k] for k in range(2)))

    def margin(f, combination, forces, blocks):  # section 7.6: -w_L in the interior of W + LS(f)
        g = [[rational(a) for a in gi] for gi in forces]
        if any(a * a + b * b >= (q[2] * fi) ** 2 for (a, b), q, fi in zip(g, pts, f) if q[2] * fi != 0):
            return False
        span = [gens[t["contact"]][t["edge"]] for t in combination]
        for (x, y, mu, _), fi in zip(pts, f):  # a point with friction reaches (1, 0, -y) and (0, 1, x)
            if mu * fi != 0:
                span += [(F(1), F(0), -y), (F(0), F(1), x)]
        for reg, blk in zip(regions, blocks):
            vs, tris = cells_of(blk)
            for t, (a, b) in zip(tris, ([rational(x) for x in gk] for gk in blk["forces"])):
                Fk, (mx, my) = cell_measures(reg, [vs[i] for i in t])
                if reg["mu"] * Fk != 0:
                    if a * a + b * b >= (reg["mu"] * Fk) ** 2:
                        return False
                    span += [(F(1), F(0), -my / Fk), (F(0), F(1), mx / Fk)]
        return any(det3(a, b, c) != 0 for a, b, c in itertools.combinations(span, 3))

    def holds(f, combination, forces, blocks):
        names = [(t["contact"], t["edge"]) for t in combination]
        if len(set(names)) != len(names):
            return "duplicate"
        total = list(load)
        for t in combination:
            i, e, w = t["contact"], t["edge"], rational(t["weight"])
            if not (type(i) is int and 0 <= i < len(gens)) or e not in gens[i]:
                return "reference"
            if w <= 0:
                return "weight"
            total = [a + w * g for a, g in zip(total, gens[i][e])]
        g = [[rational(a) for a in gi] for gi in forces]
        if len(g) != len(pts):
            return "disc"
        for (a, b), q, fi in zip(g, pts, f):
            if a * a + b * b > (q[2] * fi) ** 2:  # the closed disc
                return "disc"
            total = [total[0] + a, total[1] + b, total[2] + q[0] * b - q[1] * a]
        for reg, blk in zip(regions, blocks):  # cell forces in closed discs, at pressure centroids
            vs, tris = cells_of(blk)
            if len(blk["forces"]) != len(tris):
                return "disc"
            for t, (a, b) in zip(tris, ([rational(x) for x in gk] for gk in blk["forces"])):
                Fk, (mx, my) = cell_measures(reg, [vs[i] for i in t])
                if a * a + b * b > (reg["mu"] * Fk) ** 2:
                    return "disc"
                total = [total[0] + a, total[1] + b, total[2] + (mx * b - my * a) / Fk]
        return None if total == [0, 0, 0] else "sum"

    def fails(f, twist, u, dual, blocks, strict=True):
        t = [rational(v) for v in twist]
        if not any(t):
            return "zero twist"
        for g in (g for cc in gens for g in cc.values()):
            if sum(a * b for a, b in zip(t, g)) < 0:
                return "power"
        u = [rational(v) for v in u]
        if len(u) != len(pts) or any(v < 0 or v * v < (t[0] - t[2] * y) ** 2 + (t[1] + t[2] * x) ** 2
                                     for v, (x, y, *_) in zip(u, pts)):
            return "speed"
        if dual is None:
            bound = sum(q[2] * fi * v for q, fi, v in zip(pts, f, u))
        else:
            y = [rational(v) for v in dual]
            if any(q[3] is None and q[2] * v > y[0] + y[1] * q[0] + y[2] * q[1] for q, v in zip(pts, u)):
                return "dual"
            bound = (sum(q[2] * fi * v for q, fi, v in zip(pts, given, u) if q[3] is not None)
                     + y[0] * (W - sum(given) - fixed[0])
                     + sum(y[1 + k] * (W * c[k] - sum(fi * q[k] for fi, q in zip(given, pts)) - fixed[1][k]) for k in range(2)))
        for reg, blk in zip(regions, blocks):  # mu sum_cells sum_j w_j u_j >= mu int |v| p
            b = slide_block_bound(reg, blk, t)
            if b is None:
                return "speed"
            bound += b
        power = sum(a * b for a, b in zip(t, load))
        return None if (power > bound if strict else power >= bound) else "power"

    top_blocks = cert.get("regions", ())
    if claim is True and known:
        reason = holds(given, cert["combination"], cert.get("support_forces", []), top_blocks)
        if reason or not v3:
            return reason
        return None if margin(given, cert["combination"], cert.get("support_forces", []), top_blocks) else "margin"
    if claim is False or claim == "impending":
        if claim == "impending" and known:
            reason = holds(given, cert["combination"], cert.get("support_forces", []), top_blocks)
            if reason:
                return reason
        reason = fails(given, cert["twist"], cert.get("speed_bounds", []), None if known else cert["dual"], top_blocks,
                       claim is False)
        if reason or claim is False or known:
            return reason
    if claim == "depends":
        h, fl = cert["holding"], cert["failing"]
        f1, f2 = [rational(v) for v in h["distribution"]], [rational(v) for v in fl["distribution"]]
        if not in_F(f1) or not in_F(f2):
            return "F"
        reason = (holds(f1, h["combination"], h["support_forces"], h.get("regions", ()))
                  or fails(f2, fl["twist"], fl["speed_bounds"], None, fl.get("regions", ()), not v3))
        if reason or not v3:
            return reason
        strict = (margin(f1, h["combination"], h["support_forces"], h.get("regions", ()))
                  or fails(f2, fl["twist"], fl["speed_bounds"], None, fl.get("regions", ())) is None)
        return None if strict else "strict"
    wit = []
    for w in cert["vertices"]:
        f = [rational(v) for v in w["distribution"]]
        if not in_F(f):
            return "F"
        reason = holds(f, w["combination"], w["support_forces"], w.get("regions", ()))
        if reason:
            return reason
        if v3 and claim is True and not margin(f, w["combination"], w["support_forces"], w.get("regions", ())):
            return "margin"
        wit.append(f)
    return None if all(f in wit for f in vertices_of_F(pts, given, W, c, regions)) else "vertex"


def verify_quality(scene, cert):
    """Section 3.4: the grasp quality epsilon in [lower, upper]; None if proved, else a short reason."""
    if cert.get("wrenchkit_certificate") != 4:
        return "header"
    norm, normalize, s = cert["norm"], cert["normalize"], rational(cert["torque_scale"])
    radius = "torque_radius_squared" in cert  # s = 1/sqrt(r2) within its error
    eta = rational(cert["torque_scale_error"]) if radius else F(0)
    if radius:
        r2 = rational(cert["torque_radius_squared"])
        if r2 <= 0 or eta < 0 or (eta == 0 and s * s * r2 != 1) or (
                eta > 0 and (s - eta < 0 or (s - eta) ** 2 * r2 > 1 or (s + eta) ** 2 * r2 < 1)):
            return "torque"
    ax, ay = (rational(v) for v in cert["about"])
    eps = cert["epsilon"]
    lower, upper = rational(eps["lower"]), rational(eps["upper"])
    if s <= 0 or lower < 0 or lower > upper:
        return "bracket"
    contacts = scene.get("contacts", [])
    gens = [generators(c, True) for c in contacts]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))  # noqa: E731
    cross = lambda u, v: (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])  # noqa: E731
    sub = lambda a, b: tuple(x - y for x, y in zip(a, b))  # noqa: E731
    if upper == 0:  # not in force closure: a twist with power >= 0 against every edge
        t = [rational(v) for v in cert["twist"]]
        if all(v == 0 for v in t):
            return "zero twist"
        if any(dot(t, w) < 0 for g in gens for w in g.values()):
            return "power"
        return None
    scales = cert["scales"]
    if len(scales) != len(contacts):
        return "scales"
    points, owner, delta_max, delta_sum, exact = [], [], F(0), F(0), True
    for i, (c, g) in enumerate(zip(contacts, gens)):
        sc, err, bound = (rational(scales[i][k]) for k in ("scale", "error", "bound"))
        edges = [g[e] for e in ("left", "right", "normal", "wrench") if e in g]
        moments = [m - (ax * fy - ay * fx) for fx, fy, m in edges]
        u = [(fx, fy, s * mm) for (fx, fy, _), mm in zip(edges, moments)]
        if "wrench" in c or normalize == "as-given":
            q = F(1)
        elif normalize == "unit-force":
            q = u[0][0] ** 2 + u[0][1] ** 2
        else:
            nx, ny = (number(v) for v in c["normal"])
            q = nx * nx + ny * ny
        if err == 0:
            if sc * sc * q != 1:
                return "scale"
        elif sc - err < 0 or (sc - err) ** 2 * q > 1 or (sc + err) ** 2 * q < 1:
            return "scale"
        top = s + eta
        if any(bound * bound < x[0] ** 2 + x[1] ** 2 + top * top * mm * mm for x, mm in zip(u, moments)):
            return "bound"
        mb = rational(scales[i]["moment_bound"]) if radius else F(0)
        if radius and any(mb * mb < mm * mm for mm in moments):
            return "bound"
        exact = exact and err == 0 and eta == 0
        d = err * bound + sc * mb * eta
        delta_max, delta_sum = max(delta_max, d), delta_sum + d
        for x in u:
            points.append(tuple(sc * v for v in x))
            owner.append(i)
    if exact != ("squared" in eps):
        return "squared"
    if norm == "L1":
        tris, seen, best = cert["boundary"], set(), None
        for t in tris:
            a, b, c = (points[k] for k in t)
            n = cross(sub(b, a), sub(c, a))
            off = dot(n, a)
            if off <= 0:
                return "orientation"
            if any(dot(n, p) > off for p in points):
                return "support"
            for k in range(3):
                e = (t[k], t[(k + 1) % 3])
                if e in seen:
                    return "surface"
                seen.add(e)
            d = off * off / dot(n, n)
            best = d if best is None else min(best, d)
        if any((b, a) not in seen for a, b in seen):
            return "surface"
        if cert["nearest"] not in tris:
            return "nearest"
        delta = delta_max
    else:
        groups = [[p for p, o in zip(points, owner) if o == i] for i in range(len(contacts))]
        edges = [g + ([sub(g[0], g[1])] if len(g) == 2 else []) for g in groups]
        normals = [cross(*g) for g in groups if len(g) == 2]
        normals += [cross(e, f) for i in range(len(groups)) for j in range(i + 1, len(groups)) for e in edges[i] for f in edges[j]]
        h = lambda d: sum(max([F(0)] + [dot(d, x) for x in g]) for g in groups)  # noqa: E731
        values = [h(d) ** 2 / dot(d, d) for n in normals if any(n) for d in (n, tuple(-v for v in n))]
        if not values or min(values) <= 0:
            return "closure"
        best = min(values)
        n = [rational(v) for v in cert["normal"]]
        if not any(n) or h(n) ** 2 / dot(n, n) != best:
            return "normal"
        delta = delta_sum
    if exact and rational(eps["squared"]) != best:
        return "squared"
    if (lower + delta) ** 2 > best:
        return "lower"
    if upper - delta < 0 or (upper - delta) ** 2 < best:
        return "upper"
    return None


def verify_critical(scene, cert):
    """Section 3.5: the critical friction coefficient; None if proved, else a short reason."""
    if cert.get("wrenchkit_certificate") != 4:
        return "header"
    of = cert["of"]
    balance = of == "equilibrium"
    if balance and load_wrench(scene) is None:
        return "no load"

    proportional = cert.get("scaling", "common") == "proportional"
    if proportional and balance:
        return "scaling"

    def at_mu(mu):
        s = json.loads(json.dumps(scene))
        for c in s.get("contacts", []):
            if "wrench" not in c:
                c["mu"] = str(mu * number(c.get("mu", 0)) if proportional else mu)
        return s

    def side(key, holds):
        sd = cert[key]
        c = sd["certificate"]
        if c.get("property") != of or c.get("wrenchkit_certificate") not in (1, 2, 3) or c.get("holds") is not holds:
            return "nested"
        return None if verify(at_mu(rational(sd["mu"])), c) is None else "nested"

    def families():
        out = []
        for c in scene.get("contacts", []):
            if "wrench" in c:
                out.append((tuple(number(v) for v in c["wrench"]), (0, 0, 0)))
                continue
            (px, py), (nx, ny) = (number(v) for v in c["at"]), (number(v) for v in c["normal"])
            w = number(c.get("mu", 0)) if proportional else 1
            a, b = (nx, ny, px * ny - py * nx), (-ny * w, nx * w, (px * nx + py * ny) * w)
            out += [(a, b), (a, tuple(-v for v in b))]
        if balance:
            out.append((load_wrench(scene), (0, 0, 0)))
        return out

    def minors(maximal):  # every minor, or the 3x3 ones alone (closure: the chirotope, in rank 3)
        F = families()
        cr = lambda u, v: (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])  # noqa: E731
        dt = lambda x, y, z: sum(p * q for p, q in zip(x, cr(y, z)))  # noqa: E731
        out = [] if maximal else [[f[0][k], f[1][k]] for f in F for k in range(3)]
        for (A, a), (B, b) in [] if maximal else itertools.combinations(F, 2):
            c0, c2, u, v = cr(A, B), cr(a, b), cr(A, b), cr(a, B)
            out += [[c0[k], u[k] + v[k], c2[k]] for k in range(3)]
        for (A, a), (B, b), (C, c) in itertools.combinations(F, 3):
            out.append([dt(A, B, C), dt(a, B, C) + dt(A, b, C) + dt(A, B, c), dt(A, b, c) + dt(a, B, c) + dt(a, b, C), dt(a, b, c)])
        return out

    def mul(p, q):
        r = [F(0)] * (len(p) + len(q) - 1)
        for i, x in enumerate(p):
            for j, y in enumerate(q):
                r[i + j] += x * y
        return r

    def one_sign(q):
        signs = [x > 0 for x in q if x != 0]
        return all(x == signs[0] for x in signs)

    def value(p, x):
        return sum(c * x ** k for k, c in enumerate(p))

    def constant(p, l, h, closed_end):  # identically 0, or nonzero at closed_end and no root in (l, h) (Descartes)
        if all(c == 0 for c in p):
            return True
        if value(p, closed_end) == 0:
            return False
        d, q = len(p) - 1, [F(0)] * len(p)
        for k, c in enumerate(p):
            t = [c]
            for _ in range(k):
                t = mul(t, [l, h])
            for _ in range(d - k):
                t = mul(t, [1, 1])
            q = [x + y for x, y in zip(q, t)]
        return one_sign(q)

    claim = cert["critical_mu"]
    if claim == "always":
        return side("above", True) if rational(cert["above"]["mu"]) == 0 else "always"
    if claim == "never":
        if "limit_twist" not in cert:
            return "never"
        t = [rational(v) for v in cert["limit_twist"]]
        dot = lambda x, y: sum(p * q for p, q in zip(x, y))  # noqa: E731
        if not any(t) or any(dot(t, a) < 0 or dot(t, b) != 0 for a, b in families()[:len(families()) - balance]):
            return "limit_twist"
        if balance and dot(t, load_wrench(scene)) <= 0:
            return "limit_twist"
        return None
    lower, upper = rational(claim["lower"]), rational(claim["upper"])
    below, above = rational(cert["below"]["mu"]), rational(cert["above"]["mu"])
    for key, holds in (("below", False), ("above", True)):
        reason = side(key, holds)
        if reason:
            return reason
    if not (0 <= lower <= upper) or below >= above:
        return "bracket"
    if not cert.get("constant"):
        return None if (below, above) == (lower, upper) else "bracket"
    if lower != upper or lower not in (below, above):
        return "bracket"
    mu = lower
    far = above if mu == below else below
    l, h = min(mu, far), max(mu, far)
    return None if all(constant(p, l, h, far) for p in minors(not balance)) else "constant"


def verify_triples(scene, cert):
    """§3.6 with three fingers: every triple asked, in order; each claimed cube's placements (its corners, centre and a
    5x5x5 grid) close — decided here by whether the six friction-cone wrenches positively span the wrench space (no
    plane through the origin and two of them has all six on one side, and they have rank 3), not by the certificate's
    four wrenches —, and a triple claimed "never" has no closing placement on a 6x6x6 grid, with its direction's
    claim (every wrench at both ends of each edge on the non-positive side, or mu = 0) checked."""
    V = [(F(x), F(y)) for x, y in scene["body"]["outline"]]
    n, mu = len(V), F(cert["mu"])
    area2 = sum(V[k][0] * V[(k + 1) % n][1] - V[(k + 1) % n][0] * V[k][1] for k in range(n))

    def cone(k):  # first vertex, vector, the cone's two edges n -/+ mu rot90 n
        dx, dy = V[(k + 1) % n][0] - V[k][0], V[(k + 1) % n][1] - V[k][1]
        nx, ny = (-dy, dx) if area2 > 0 else (dy, -dx)
        tx, ty = -ny, nx
        return V[k], (dx, dy), [(nx - mu * tx, ny - mu * ty), (nx + mu * tx, ny + mu * ty)]

    def wrenches(edges, s):
        out = []
        for e, t in zip(edges, s):
            a, d, fs = cone(e)
            px, py = a[0] + t * d[0], a[1] + t * d[1]
            out += [(fx, fy, px * fy - py * fx) for fx, fy in fs]
        return out

    def crossv(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def dotv(a, b):
        return sum(x * y for x, y in zip(a, b))

    def spans(W):
        if not any(det3(a, b, c) != 0 for a, b, c in itertools.combinations(W, 3)):
            return False  # rank below 3
        for a, b in itertools.combinations(W, 2):
            u = crossv(a, b)
            if any(u) and (all(dotv(u, w) <= 0 for w in W) or all(dotv(u, w) >= 0 for w in W)):
                return False
        return True

    edges = cert.get("edges", list(range(n)))
    want = [tuple(t) for t in itertools.combinations(edges, 3)]
    if [tuple(t["edges"]) for t in cert["triples"]] != want:
        return "triples"
    for t in cert["triples"]:
        e = t["edges"]
        if "independent" in t:
            box = [(F(a), F(b)) for a, b in t["independent"]]
            if not all(0 <= a < b <= 1 for a, b in box):
                return "independent"
            grid = [[a + (b - a) * F(k, 4) for k in range(5)] for a, b in box]
            if not all(spans(wrenches(e, s)) for s in itertools.product(*grid)):
                return "independent"
        if "never" in t:
            if "independent" in t:
                return "never"
            if t["never"] == "frictionless":
                if mu != 0:
                    return "never"
            else:
                u = [F(x) for x in t["never"]]
                if not any(u) or any(dotv(u, w) > 0 for s in itertools.product((F(0), F(1)), repeat=3) for w in wrenches(e, s)):
                    return "never"
            if any(spans(wrenches(e, s)) for s in itertools.product([F(k, 5) for k in range(6)], repeat=3)):
                return "never"
    return None


def verify_regions(scene, cert):
    """§3.6: every pair asked, in order, with Nguyen's region (written here from angles' signs: the segment between
    the fingers strictly inside both cones), cut from the unit square; its own clipping, not the checker's."""
    if cert.get("wrenchkit_certificate") == 5 and cert.get("fingers") == 3 and "pairs" not in cert:
        return verify_triples(scene, cert)
    if cert.get("wrenchkit_certificate") != 5 or cert.get("fingers") != 2:
        return "header"
    V = [(F(x), F(y)) for x, y in scene["body"]["outline"]]
    n, mu = len(V), F(cert["mu"])
    area2 = sum(V[k][0] * V[(k + 1) % n][1] - V[(k + 1) % n][0] * V[k][1] for k in range(n))

    def inward(k):
        dx, dy = V[(k + 1) % n][0] - V[k][0], V[(k + 1) % n][1] - V[k][1]
        return (-dy, dx) if area2 > 0 else (dy, -dx)

    def closes(i, s, j, t):
        p = (V[i][0] + s * (V[(i + 1) % n][0] - V[i][0]), V[i][1] + s * (V[(i + 1) % n][1] - V[i][1]))
        q = (V[j][0] + t * (V[(j + 1) % n][0] - V[j][0]), V[j][1] + t * (V[(j + 1) % n][1] - V[j][1]))
        ok = True
        for nn, d in ((inward(i), (q[0] - p[0], q[1] - p[1])), (inward(j), (p[0] - q[0], p[1] - q[1]))):
            along, side = nn[0] * d[0] + nn[1] * d[1], nn[0] * d[1] - nn[1] * d[0]
            ok = ok and along > 0 and abs(side) < mu * along
        return ok

    edges = cert.get("edges", list(range(n)))
    want = [(i, j) for a, i in enumerate(edges) for j in edges[a + 1:]]
    if [tuple(p["edges"]) for p in cert["pairs"]] != want:
        return "pairs"
    for p in cert["pairs"]:
        i, j = p["edges"]
        # the claim: the open polygon is the closure set. Test it on a grid of the square: a point strictly inside a
        # claimed polygon closes, a point outside every claimed polygon (and off their sides) does not
        polys = [[(F(a), F(b)) for a, b in poly] for poly in p["closed"]]
        if "independent" in p:  # every corner closes (the region is convex)
            (s0, s1), (t0, t1) = [(F(a), F(b)) for a, b in p["independent"]]
            if not (0 <= s0 < s1 <= 1 and 0 <= t0 < t1 <= 1):
                return "independent"
            if not all(closes(i, s, j, t) for s in (s0, s1) for t in (t0, t1)):
                return "independent"

        def where(s, t):
            for poly in polys:
                signs = [(b[0] - a[0]) * (t - a[1]) - (b[1] - a[1]) * (s - a[0]) for a, b in zip(poly, poly[1:] + poly[:1])]
                if all(x > 0 for x in signs):
                    return "in"
                if all(x >= 0 for x in signs):
                    return "side"
            return "out"
        for a in range(0, 25):
            for b in range(0, 25):
                s, t = F(a, 24), F(b, 24)
                w = where(s, t)
                if w != "side" and (w == "in") != closes(i, s, j, t):
                    return "region"
    return None


def verify_contact(c, pts, known, p, n, mu, v):
    """Section 8.2: the contact mode (PU-2), support points with every force given. None if proved, else a reason."""
    if set(c) - {"mode", "bits", "omega", "tangent_omega", "tangent_pivot", "sliding", "pivot", "force"} or not {"mode", "bits", "omega"} <= set(c) or not known:
        return "contact"
    if ("force" in c) != ("pivot" in c and c["mode"] == "sticks"):
        return "contact"
    if "sliding" in c and c["mode"] not in ("slides left", "slides right"):
        return "contact"
    bits = c["bits"]

    def root_bounds(s):
        return sqrt_bounds(s, bits)

    rho = [(q[0], q[1], q[2] * q[3]) for q in pts]

    def interval(u, l, moment, a, b, slip=None, w=None):
        """sum rho (l . v(x)) / |v(x)| over x in [a, b]; None if a speed may vanish. v(x) = u + x rot90(r - p), or
        with slip: u + w rot90(r - p) + x slip."""
        lo = hi = F(0)
        for x, y, r in rho:
            if r == 0:
                continue
            dx, dy = x - p[0], y - p[1]
            rx, ry = -dy, dx
            bx, by = (u[0] + w * rx, u[1] + w * ry) if slip else u
            wx, wy = slip if slip else (rx, ry)
            lx, ly = (rx, ry) if moment else l
            c0, c1 = lx * bx + ly * by, lx * wx + ly * wy
            n0, n1 = sorted((c0 + a * c1, c0 + b * c1))
            uu, uw, dd = bx * bx + by * by, bx * wx + by * wy, wx * wx + wy * wy
            quad = lambda t: uu + 2 * t * uw + t * t * dd  # noqa: E731
            qs = [quad(a), quad(b)]
            if dd and a <= -uw / dd <= b:
                qs.append(quad(-uw / dd))
            if min(qs) <= 0:
                return None
            slo, shi = root_bounds(min(qs))[0], root_bounds(max(qs))[1]
            if n0 >= 0:
                t0, t1 = n0 / shi, n1 / slo
            elif n1 <= 0:
                t0, t1 = n0 / slo, n1 / shi
            else:
                t0, t1 = n0 / slo, n1 / slo
            lo, hi = lo + r * t0, hi + r * t1
        return lo, hi

    def bracketed(u, w):  # the root of the moment about p in [w0, w1]: negative at w0, positive at w1
        w0, w1 = (rational(x) for x in w)
        if w0 == w1:
            return w0 == 0 and sum(r * ((x - p[0]) * u[1] - (y - p[1]) * u[0]) for x, y, r in rho) == 0
        if w0 > w1:
            return False
        g0, g1 = interval(u, None, True, w0, w0), interval(u, None, True, w1, w1)
        return g0 is not None and g1 is not None and g0[1] < 0 and g1[0] > 0

    def force_sign(u, w, l):
        w0, w1 = (rational(x) for x in w)
        if w0 == w1:
            t = l[0] * u[0] + l[1] * u[1]
            return 3 if t == 0 else (t > 0) - (t < 0)
        iv = interval(u, l, False, w0, w1)
        return 0 if iv is None else (1 if iv[0] > 0 else -1 if iv[1] < 0 else 0)

    eL, eR = (n[0] - mu * n[1], n[1] + mu * n[0]), (n[0] + mu * n[1], n[1] - mu * n[0])
    rl, rr = (-eL[1], eL[0]), (-eR[1], eR[0])  # rot90(e) . F = e x F

    def facet_rest(j, u, w):
        """PU-2 sections 6-8: the other points' force F' and moment M' about p at the rotation about point j."""
        nonlocal rho
        keep = rho
        rho = [q for i, q in enumerate(keep) if i != j]
        fx, fy, m = interval(u, (1, 0), False, w, w), interval(u, (0, 1), False, w, w), interval(u, None, True, w, w)
        rho = keep
        return None if None in (fx, fy, m) else (fx, fy, m)

    def facet_holds(j, u, w, e):
        """PU-2 sections 6-7: the facet of the rotation about point j (rate w, velocity u at p) holds a force along e
        through p: lambda = (d x F' - M') / (d x e) > 0 and |lambda e - F'|^2 < rho_j^2, F', M' the others' bounds."""
        (xj, yj, rj), d = rho[j], (rho[j][0] - p[0], rho[j][1] - p[1])
        de = d[0] * e[1] - d[1] * e[0]
        rest = facet_rest(j, u, w)
        if rj == 0 or de == 0 or rest is None:
            return False
        fx, fy, m = rest
        num = sorted((d[0] * fy[0], d[0] * fy[1]))
        num2 = sorted((-d[1] * fx[0], -d[1] * fx[1]))
        lam = sorted(((num[0] + num2[0] - m[1]) / de, (num[1] + num2[1] - m[0]) / de))
        gx = sorted((e[0] * lam[0], e[0] * lam[1]))
        gy = sorted((e[1] * lam[0], e[1] * lam[1]))
        g2 = max((gx[0] - fx[1]) ** 2, (gx[1] - fx[0]) ** 2) + max((gy[0] - fy[1]) ** 2, (gy[1] - fy[0]) ** 2)
        return lam[0] > 0 and g2 < rj * rj

    def facet_beyond(j, u, w, l):
        """PU-2 section 8: the facet's forces through p (the chord d x F = d x F' - M', |F - F'| <= rho_j) are not
        empty (M'^2 < rho_j^2 |d|^2) and all have l . F > 0: A = |d|^2 l . F' - M' l . rot90 d > 0 and
        A^2 > (l . d)^2 (rho_j^2 |d|^2 - M'^2)."""
        rj, d = rho[j][2], (rho[j][0] - p[0], rho[j][1] - p[1])
        rest = facet_rest(j, u, w)
        if rj == 0 or rest is None:
            return False
        fx, fy, m = rest
        dd = d[0] * d[0] + d[1] * d[1]
        reach, m2 = rj * rj * dd, sorted((m[0] * m[0], m[1] * m[1]))
        if not m2[1] < reach:
            return False
        m2_min = 0 if m[0] <= 0 <= m[1] else m2[0]
        a = min(l[0] * dd * fx[0], l[0] * dd * fx[1]) + min(l[1] * dd * fy[0], l[1] * dd * fy[1])
        k = -(l[0] * -d[1] + l[1] * d[0])
        big = a + min(k * m[0], k * m[1])
        ld = l[0] * d[0] + l[1] * d[1]
        return big > 0 and big * big > ld * ld * (reach - m2_min)

    def pivot_rate(j, u):  # the rotation about point j moving p with u (u . d = 0): its rate, or None
        if not isinstance(j, int) or not 0 <= j < len(rho):
            return None
        d = (rho[j][0] - p[0], rho[j][1] - p[1])
        dd = d[0] * d[0] + d[1] * d[1]
        if dd == 0 or u[0] * d[0] + u[1] * d[1] != 0:
            return None
        return (u[0] * d[1] - u[1] * d[0]) / dd

    mode = c["mode"]
    if "pivot" in c:  # sections 7-8: the sticking motion the rotation about point j
        j = c["pivot"]
        w = pivot_rate(j, v)
        if w is None or [rational(x) for x in c["omega"]] != [w, w]:
            return "contact"
        if mode == "sticks":  # a force of its facet along "force", inside the cone
            e = tuple(rational(x) for x in c["force"])
            inside = rr[0] * e[0] + rr[1] * e[1] > 0 and -rl[0] * e[0] - rl[1] * e[1] > 0
            return None if inside and facet_holds(j, v, w, e) else "contact"
    else:
        if not bracketed(v, c["omega"]):
            return "contact"
        right, left = force_sign(v, c["omega"], rr), force_sign(v, c["omega"], (-rl[0], -rl[1]))
        if mode == "sticks":
            return None if mu > 0 and right == 1 and left == 1 else "contact"
        if mode == "impending":
            return None if 3 in (right, left) else "contact"
    if mode not in ("slides left", "slides right") or "tangent_omega" not in c:
        return "contact"
    t = (-n[1], n[0])
    e = rl if mode == "slides left" else rr
    if "tangent_pivot" in c:  # F(t) the chord of a facet (section 8): every force of it on e's left
        k = c["tangent_pivot"]
        wt = pivot_rate(k, t)
        in_h = 1 if wt is not None and [rational(x) for x in c["tangent_omega"]] == [wt, wt] and facet_beyond(k, t, wt, e) else 0
    else:
        if not bracketed(t, c["tangent_omega"]):
            return "contact"
        in_h = force_sign(t, c["tangent_omega"], e)
    sign = 1 if mode == "slides left" else -1
    if "pivot" in c:  # every force of the sticking pivot's facet beyond the edge
        beyond = 1 if facet_beyond(c["pivot"], v, w, (sign * e[0], sign * e[1])) else 0
    else:
        beyond = sign * force_sign(v, c["omega"], e)
    if in_h != 1 or beyond != 1:
        return "contact"
    if "sliding" not in c:
        return None
    # the sliding motion (PU-2 section 5): the velocity at p is v + x t, its force along e (e x F rises with x)
    sl = c["sliding"]
    if set(sl) not in ({"slip", "slip_omega", "omega"}, {"pivot", "slip", "omega"}):
        return "contact"
    x0, x1 = (rational(q) for q in sl["slip"])
    w0, w1 = (rational(q) for q in sl["omega"])
    at = lambda x: (v[0] + x * t[0], v[1] + x * t[1])  # noqa: E731
    if x0 > x1 or w0 > w1:
        return "contact"
    if "pivot" in sl:  # section 6: the rotation about support point j, its facet holding a force along the edge
        j = sl["pivot"]
        if not isinstance(j, int) or not 0 <= j < len(rho):
            return "contact"
        (xj, yj, rj), d = rho[j], (rho[j][0] - p[0], rho[j][1] - p[1])
        ed = (e[1], -e[0])  # the edge, e here being rot90 of it
        td, de = t[0] * d[0] + t[1] * d[1], d[0] * ed[1] - d[1] * ed[0]
        if rj == 0 or td == 0 or de == 0:
            return "contact"
        x = -(v[0] * d[0] + v[1] * d[1]) / td
        u = at(x)
        w = (u[0] * d[1] - u[1] * d[0]) / (d[0] * d[0] + d[1] * d[1])
        if (x <= 0 if mode == "slides right" else x >= 0) or (x0, x1, w0, w1) != (x, x, w, w):
            return "contact"
        return None if facet_holds(j, u, w, ed) else "contact"
    if x0 == x1:  # the translation along e through c
        u = at(x0)
        g0 = sum(r * ((x - p[0]) * u[1] - (y - p[1]) * u[0]) for x, y, r in rho)
        along = e[1] * u[0] - e[0] * u[1]  # e . u, e = (l_y, -l_x)
        ok = w0 == w1 == 0 and g0 == 0 and e[0] * u[0] + e[1] * u[1] == 0 and along > 0 and sum(r for _, _, r in rho) > 0
        return None if ok else "contact"
    for k, x in enumerate((x0, x1)):
        u = at(x)
        if not bracketed(u, sl["slip_omega"][k]) or force_sign(u, sl["slip_omega"][k], e) != (-1 if k == 0 else 1):
            return "contact"
    for k, w in enumerate((w0, w1)):
        iv = interval(v, None, True, x0, x1, t, w)
        if iv is None or (iv[1] >= 0 if k == 0 else iv[0] <= 0):
            return "contact"
    return None


def sqrt_bounds(s, bits):
    """lo <= sqrt(s) <= hi for a Fraction s >= 0: isqrt(num den 4^B) / (den 2^B), B = bits + the bit length of den
    (the engine's and the checker's precision for the same bits)."""
    if s == 0:
        return F(0), F(0)
    b = bits + s.denominator.bit_length()
    x = s.numerator * s.denominator << (2 * b)
    r = math.isqrt(x)
    return F(r, s.denominator << b), F(r + (r * r != x), s.denominator << b)


def correction(R, d, al):
    """PU-3 section 5's E at the bounds (grows with R and alpha, falls with d)."""
    K = R * (2 * al + R) / (2 * d - R)
    return K * K * (2 * d + R) / (8 * d) + al * R ** 3 / (d * (2 * d - R))


def verify_locus(loc, S, c, p, n, mu, v, rotation):
    """Section 8.4 (PU-4): the rotation centres' pieces, each sense the rotation allows: the half-planes from the scene,
    a bounded piece with no direction of recession and every vertex in its polygon, the arm above every vertex."""
    if set(loc) - {"R_hi", "alpha_hi", "T", "ccw", "cw", "arm_hi"} or not {"R_hi", "ccw", "cw"} <= set(loc):
        return "keys"
    dot = lambda a, b: a[0] * b[0] + a[1] * b[1]  # noqa: E731
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]  # noqa: E731
    R2 = max(dot((x[0] - c[0], x[1] - c[1]), (x[0] - c[0], x[1] - c[1])) for x in S)
    R = rational(loc["R_hi"])
    if R < 0 or R * R < R2:
        return "locus"
    a = (c[0] - p[0], c[1] - p[1])
    tip = "T" in loc
    if tip:
        al, T = rational(loc["alpha_hi"]), rational(loc["T"])
        if al <= 0 or al * al < dot(a, a) or T <= 0 or T / al <= R or T < R2 + correction(R, T / al, al):
            return "locus"
    eL, eR = (n[0] - mu * n[1], n[1] + mu * n[0]), (n[0] + mu * n[1], n[1] - mu * n[0])
    pv, H, unbounded = dot(p, v), F(0), False
    for name, s in (("ccw", 1), ("cw", -1)):
        if loc[name] is None:
            if rotation not in ({"ccw": "cw", "cw": "ccw"}[name], "none"):
                return "sense"
            continue
        if [q.get("mode") for q in loc[name]] != ["sticks", "slides left", "slides right"]:
            return "keys"
        for m, piece in enumerate(loc[name]):
            hs = [((2 * (p[0] - c[0]), 2 * (p[1] - c[1])), dot(p, p) - dot(c, c)), ((s * n[1], -s * n[0]), s * cross(p, n))]
            if tip:
                hs.append((a, T + dot(a, c)))
            if m == 0:
                hs += [((-s * eL[0], -s * eL[1]), -min(s * dot(x, eL) for x in S)),
                       ((s * eR[0], s * eR[1]), max(s * dot(x, eR) for x in S)), (v, pv), ((-v[0], -v[1]), -pv)]
            else:
                e, t = (eL, s) if m == 1 else (eR, -s)
                hs += [(e, max(dot(x, e) for x in S)), ((-e[0], -e[1]), -min(dot(x, e) for x in S)),
                       ((-t * v[0], -t * v[1]), -t * pv)]
            if not piece["bounded"]:
                unbounded = True
                continue
            for h in hs:  # a direction of recession: along some boundary line, inside every half-plane
                for u in ((-h[0][1], h[0][0]), (h[0][1], -h[0][0])):
                    if u != (0, 0) and all(dot(g[0], u) <= 0 for g in hs):
                        return "unbounded"
            poly = [tuple(rational(x) for x in q) for q in piece["polygon"]]
            for g, h in itertools.combinations(hs, 2):
                det = cross(g[0], h[0])
                if det == 0:
                    continue
                q = ((g[1] * h[0][1] - h[1] * g[0][1]) / det, (g[0][0] * h[1] - h[0][0] * g[1]) / det)
                if any(dot(k[0], q) > k[1] for k in hs):
                    continue
                if len(poly) == 1:
                    inside = poly[0] == q
                elif len(poly) == 2:
                    d, w = (poly[1][0] - poly[0][0], poly[1][1] - poly[0][1]), (q[0] - poly[0][0], q[1] - poly[0][1])
                    inside = cross(d, w) == 0 and 0 <= dot(d, w) <= dot(d, d)
                else:
                    inside = len(poly) > 0 and all(
                        cross((b[0] - a_[0], b[1] - a_[1]), (q[0] - a_[0], q[1] - a_[1])) >= 0
                        for a_, b in zip(poly, poly[1:] + poly[:1]))
                if not inside:
                    return "polygon"
                H = max(H, s * cross((p[0] - q[0], p[1] - q[1]), n))
    if "arm_hi" in loc:
        arm = rational(loc["arm_hi"])
        if unbounded or arm < 0 or arm * arm * dot(n, n) < H * H:
            return "arm"
    return None


def verify_line_push(scene, cert):
    """Section 8.3 (PU-3): a line pusher's stable push, over a support of points (regions are the C++ checker's)."""
    if set(cert) - {"wrenchkit_certificate", "property", "rotation", "center", "stable", "region"} or "center" not in cert:
        return "keys"
    sup, pu, st = scene["support"], scene["pusher"], cert["stable"]
    if sup.get("regions"):
        return "unsupported"
    pts = [(number(q["at"][0]), number(q["at"][1]), number(q.get("mu", sup.get("mu", 0))),
            None if "force" not in q else number(q["force"])) for q in sup["points"]]
    if any(q[3] is None for q in pts):
        return "unsupported"  # forces not given: the C++ checker's
    e = [[number(a) for a in end] for end in pu["segment"]]
    (nx, ny), (vx, vy) = ([number(a) for a in pu[k]] for k in ("normal", "velocity"))
    mu, w = number(pu.get("mu", scene.get("mu", 0))), number(pu.get("omega", 0))
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]  # noqa: E731
    dot = lambda a, b: a[0] * b[0] + a[1] * b[1]  # noqa: E731
    sub = lambda a, b: (a[0] - b[0], a[1] - b[1])  # noqa: E731
    along = sub(e[1], e[0])
    if dot(along, (nx, ny)) != 0 or vx * nx + vy * ny <= 0:
        return "pusher"
    s_end = [1, -1] if cross(along, (nx, ny)) > 0 else [-1, 1]
    eL, eR = (nx - mu * ny, ny + mu * nx), (nx + mu * ny, ny - mu * nx)
    D = sum(q[2] * q[3] for q in pts)
    c = tuple(sum(q[2] * q[3] * q[k] for q in pts) / D for k in range(2))
    if [rational(v) for v in cert["center"]] != list(c):
        return "center"
    S = [(q[0], q[1]) for q in pts if q[2] > 0]
    R2 = max(dot(sub(x, c), sub(x, c)) for x in S)
    if rational(st["R2"]) != R2:
        return "R2"
    if "region" in cert:  # each sense's tip line a.(q - c) >= T: T / alpha_hi > R_hi, T >= R^2 + E(T / alpha_hi)
        reg = cert["region"]
        R = rational(reg["R_hi"])
        if R < 0 or R * R < R2:
            return "region"
        for k, sg in (("ccw", 1), ("cw", -1)):
            if reg[k] is None:
                continue
            t = 1 if s_end[0] * sg > 0 else 0
            a = sub(c, e[t])
            al, T = rational(reg[k]["alpha_hi"]), rational(reg[k]["T"])
            if al <= 0 or al * al < dot(a, a) or T <= 0 or T / al <= R or T < R2 + correction(R, T / al, al):
                return "region"
        for v in reg.get("translations", []):
            v = [rational(x) for x in v]
            if (cross(v, eL) < 0 or cross(eR, v) < 0 or any(s_end[k] * cross(sub(c, e[k]), v) < 0 for k in (0, 1))
                    or dot(v, (nx, ny)) <= 0):
                return "region"
    stable = st["verdict"] == "stable"
    sense = (w > 0) - (w < 0)
    corners = {(1 if v > 0 else -1 if v < 0 else 0) for v in (cross(sub(x, c), d) for x in e for d in (eL, eR))}
    alike = {1: "ccw", -1: "cw"}.get(corners.pop()) if len(corners) == 1 else None
    if stable and cert.get("rotation") != {1: "ccw", -1: "cw", 0: "none"}[sense]:
        return "rotation"
    if not stable and cert.get("rotation") not in (None, alike):
        return "rotation"
    if stable == ("facet" in st):
        return "facet"
    names = ["left edge", "right edge", "end 0", "end 1"]
    if w == 0:
        vals = [cross((vx, vy), eL), cross(eR, (vx, vy))] + [s_end[k] * cross(sub(c, e[k]), (vx, vy)) for k in (0, 1)]
        if stable:
            return "facet" if any(v < 0 for v in vals) else None
        return None if vals[names.index(st["facet"])] < 0 else "facet"
    m = ((e[0][0] + e[1][0]) / 2, (e[0][1] + e[1][1]) / 2)
    q = (m[0] - vy / w, m[1] + vx / w)

    def h(f, x):
        xq = sub(x, q)
        if f < 2:
            return sense * dot(xq, eL) if f == 0 else -sense * dot(xq, eR)
        return -s_end[f - 2] * sense * dot(sub(x, e[f - 2]), xq)

    if not stable:
        wit, f = st["witness"], names.index(st["facet"])
        xs, ws = [tuple(rational(a) for a in x) for x in wit["points"]], [rational(a) for a in wit["weights"]]
        if len(xs) != len(ws) or any(x not in S for x in xs) or any(a <= 0 for a in ws):
            return "witness"
        if any(sum(a * (x[k] - c[k]) for a, x in zip(ws, xs)) != 0 for k in (0, 1)):
            return "witness"
        lo = F(0)
        for a, x in zip(ws, xs):
            l0, l1 = sqrt_bounds(dot(sub(x, q), sub(x, q)), wit["bits"])
            t = a * h(f, x)
            lo += t / l1 if t >= 0 else t / l0
        return None if lo > 0 else "witness"
    duals = {names.index(k): [rational(a) for a in v] for k, v in st.get("duals", {}).items()}
    for f, y in duals.items():
        if y[0] >= 0:
            return "dual"
        for x in S:
            l0, l1 = sqrt_bounds(dot(sub(x, q), sub(x, q)), st["bits"])
            t = h(f, x)
            if (t / l0 if t >= 0 else t / l1) > y[0] + y[1] * (x[0] - c[0]) + y[2] * (x[1] - c[1]):
                return "dual"
    if any(f not in duals and h(f, x) > 0 for f in (0, 1) for x in S):
        return "facet"
    b = 0 if s_end[0] * sense > 0 else 1
    t = 1 - b
    wq = sub(q, c)
    if b + 2 not in duals and dot(sub(q, e[b]), sub(q, e[b])) > dot(wq, wq):
        return "bisector"
    if t + 2 in duals:
        return None
    R, d, al = (rational(st[k]) for k in ("R_hi", "d_lo", "alpha_hi"))
    a = sub(c, e[t])
    if R < 0 or R * R < R2 or d < 0 or d * d > dot(wq, wq) or al < 0 or al * al < dot(a, a) or d <= R:
        return "bound"
    return None if dot(a, wq) >= R2 + correction(R, d, al) else "tip"


def verify_push(scene, cert):
    """Section 8 (format 6): which way a pushed body turns, by the voting rule of PU-1 section 4 over F. None if
    proved, else a short reason. Support points only (no regions); the pusher written with "at" and "normal"."""
    if cert.get("wrenchkit_certificate") != 6:
        return "header"
    if "segment" in scene.get("pusher", {}):
        return verify_line_push(scene, cert)
    keys = set(cert)
    if keys - {"wrenchkit_certificate", "property", "rotation", "friction", "votes", "center", "turns", "contact",
               "locus"} or not (
            {"rotation", "friction"} <= keys) or ({"turns"} if cert["rotation"] == "depends" else {"votes"}) - keys:
        return "keys"
    sup, pu = scene.get("support"), scene.get("pusher")
    if sup is None or pu is None:
        return "no pusher"
    if sup.get("regions") or "at" not in pu:
        return "unsupported"  # regions and placed pushers are the C++ checker's alone
    pts = [(number(q["at"][0]), number(q["at"][1]), number(q.get("mu", sup.get("mu"))),
            None if "force" not in q else number(q["force"])) for q in sup.get("points", [])]
    known = all(q[3] is not None for q in pts)
    given = [q[3] or F(0) for q in pts]
    (px, py), (nx, ny), (vx, vy) = ([number(a) for a in pu[k]] for k in ("at", "normal", "velocity"))
    mu = number(pu.get("mu", scene.get("mu", 0)))
    if vx * nx + vy * ny <= 0:
        return "velocity"
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]  # noqa: E731
    dirs = [(nx - mu * ny, ny + mu * nx), (nx + mu * ny, ny - mu * nx), (vx, vy)]  # n +- mu rot90(n), v
    fric = [q[2] for q in pts]  # D(f) = sum mu_i f_i, N_k(f) = sum mu_i f_i (p - r_i) x d_k
    votes = [[q[2] * cross((px - q[0], py - q[1]), d) for q in pts] for d in dirs]
    value = lambda coef, f: sum(a * b for a, b in zip(coef, f))  # noqa: E731
    if known:
        W, c = sum(given), None
    else:
        W = number(sup["weight"])
        c = [number(v) for v in sup.get("pressure_center", scene.get("body", {}).get("com"))]
        rest = [W - sum(given)] + [W * c[k] - sum(f * q[k] for f, q in zip(given, pts)) for k in range(2)]

    def most(coef, dual):  # max of coef.f over F by the dual [y0, yx, yy] (None if it is not feasible)
        y = [rational(v) for v in dual]
        if any(q[3] is None and a > y[0] + y[1] * q[0] + y[2] * q[1] for a, q in zip(coef, pts)):
            return None
        return value(coef, given) + sum(a * b for a, b in zip(y, rest))

    def bounds(coef, rng, lower_only):  # (L, U) proven over F, or a reason
        if set(rng) - {"lower", "dual_lower"} - (set() if lower_only else {"upper", "dual_upper"}):
            return "keys"
        duals = {"dual_lower"} | (set() if lower_only else {"dual_upper"})
        if (known and duals & set(rng)) or (not known and duals - set(rng)):
            return "dual"
        lo = hi = value(coef, given)
        if not known:
            lo, hi = most([-a for a in coef], rng["dual_lower"]), None if lower_only else most(coef, rng["dual_upper"])
            if lo is None or (hi is None and not lower_only):
                return "dual"
            lo = -lo
        L, U = rational(rng["lower"]), None if lower_only else rational(rng["upper"])
        return "bound" if L > lo or (U is not None and U < hi) else (L, U)

    def in_F(f):
        return (len(f) == len(pts) and all(v >= 0 for v in f) and all(q[3] is None or q[3] == v for q, v in zip(pts, f))
                and sum(f) == W and (known or all(value(f, [q[k] for q in pts]) == W * c[k] for k in range(2))))

    def rule(l, r, v):  # +1 ccw, -1 cw, 0 none (PU-1 section 4)
        if l and l == r:
            return l
        if l and r:
            return v
        s = l or r
        return s if s and v == s else 0

    sign = lambda x: (x > 0) - (x < 0)  # noqa: E731
    if "locus" in cert:  # one centre of friction: every force given, or one coefficient (the centre of pressure)
        if known:
            D = value(fric, given)
            cl = [sum(q[2] * f * q[k] for q, f in zip(pts, given)) / D for k in range(2)]
        elif len(set(fric)) == 1 and fric[0] > 0:
            cl = c
        else:
            return "locus"
        loc = dict(cert["locus"])
        slow, arm_lo = loc.pop("slowest", None), loc.pop("arm_lo", None)
        if (slow is None) != (arm_lo is None):
            return "keys"
        why = verify_locus(loc, [(q[0], q[1]) for q in pts if q[2] > 0], cl, (px, py), (nx, ny), mu, (vx, vy),
                           cert["rotation"])
        if why:
            return why
        if slow is not None:  # a distribution of F with a certified rate: its centre at least arm_lo from the normal line
            f = [rational(x) for x in slow.get("forces", [])]
            if not in_F(f):
                return "F"
            why = verify_contact({k: x for k, x in slow.items() if k != "forces"},
                                 [(q[0], q[1], q[2], fi) for q, fi in zip(pts, f)], True, (px, py), (nx, ny), mu, (vx, vy))
            if why:
                return why
            sticks = slow["mode"] == "sticks"
            if not sticks and not (slow["mode"] in ("slides left", "slides right") and "sliding" in slow):
                return "slowest"
            om = [rational(x) for x in (slow["omega"] if sticks else slow["sliding"]["omega"])]
            if om[0] == 0 or (om[0] > 0) != (om[1] > 0):
                return "slowest"
            fastest, vn, a = max(abs(om[0]), abs(om[1])), vx * nx + vy * ny, rational(arm_lo)
            if a < 0 or a * a * fastest * fastest * (nx * nx + ny * ny) > vn * vn:
                return "arm"
    if "contact" in cert and cert["contact"].get("mode") == "depends":  # two distributions of F, modes apart
        cc = cert["contact"]
        if set(cc) != {"mode", "witnesses"} or known or len(cc["witnesses"]) != 2:
            return "contact"
        if cc["witnesses"][0].get("mode") == cc["witnesses"][1].get("mode"):
            return "contact"
        for wt in cc["witnesses"]:
            f = [rational(x) for x in wt.get("forces", [])]
            if not in_F(f):
                return "F"
            why = verify_contact({k: x for k, x in wt.items() if k != "forces"},
                                 [(q[0], q[1], q[2], fi) for q, fi in zip(pts, f)], True, (px, py), (nx, ny), mu, (vx, vy))
            if why:
                return why
    elif "contact" in cert:
        why = verify_contact(cert["contact"], pts, known, (px, py), (nx, ny), mu, (vx, vy))
        if why:
            return why
    fr = bounds(fric, cert["friction"], True)
    if isinstance(fr, str):
        return fr
    if fr[0] <= 0:
        return "friction"
    if "center" in cert:
        cx, cy = (rational(v) for v in cert["center"])
        if known:
            D = value(fric, given)
            if (cx * D, cy * D) != tuple(sum(q[2] * f * q[k] for q, f in zip(pts, given)) for k in range(2)):
                return "center"
        elif len(set(fric)) > 1 or [cx, cy] != c:
            return "center"
    if cert["rotation"] == "depends":
        if "votes" in cert:
            return "keys"
        turns = cert["turns"]
        if set(turns) != {"ccw", "cw"}:
            return "keys"
        for want, name in ((1, "ccw"), (-1, "cw")):
            f = [rational(v) for v in turns[name]]
            if not in_F(f):
                return "F"
            if rule(*(sign(value(coef, f)) for coef in votes)) != want:
                return "turns"
        return None
    if "turns" in cert or len(cert["votes"]) != 3:
        return "keys"
    signs = []
    for coef, rng in zip(votes, cert["votes"]):
        b = bounds(coef, rng, False)
        if isinstance(b, str):
            return b
        signs.append([t for t in (-1, 0, 1) if sign(b[0]) <= t <= sign(b[1])])
    claim = {"ccw": 1, "cw": -1, "none": 0}[cert["rotation"]]
    combos = list(itertools.product(*signs))
    if any(rule(*t) != claim for t in combos):
        return "rotation"
    if not any(rule(l, r, v) == 0 and not (l and r and l != r) for l, r, v in combos):
        return None
    # "none" from an edge through c: the support's friction must not lie on one line through c (every force given)
    if not known:
        return "line"
    D = value(fric, given)
    c = [sum(q[2] * f * q[k] for q, f in zip(pts, given)) / D for k in range(2)]
    arms = [(q[0] - c[0], q[1] - c[1]) for q, f in zip(pts, given) if q[2] * f > 0]
    d = (c[0] - px, c[1] - py)
    if any(d):
        return None if any(a[0] * d[0] + a[1] * d[1] != 0 for a in arms) else "line"
    return None if any(cross(a, b) != 0 for a, b in itertools.combinations(arms, 2)) else "line"


def verify(scene, cert):
    """Returns None if cert proves its claim for scene, else a short reason."""
    if cert.get("property") == "grasp_regions":
        try:
            return verify_regions(scene, cert)
        except (ValueError, KeyError, TypeError) as e:
            return f"malformed: {e}"
    if cert.get("property") == "critical_mu":
        try:
            return verify_critical(scene, cert)
        except (ValueError, KeyError, TypeError) as e:
            return f"malformed: {e}"
    if cert.get("property") == "quality":
        try:
            return verify_quality(scene, cert)
        except (ValueError, KeyError, TypeError) as e:
            return f"malformed: {e}"
    if cert.get("property") == "push":
        try:
            return verify_push(scene, cert)
        except (ValueError, KeyError, TypeError) as e:
            return f"malformed: {e}"
    keys = set(cert)
    allowed = {"wrenchkit_certificate", "property", "holds", "combination", "independent", "twist", "reading",
               "load", "motion", "support_forces", "speed_bounds", "dual", "vertices", "sticking", "sliding",
               "holding", "failing", "regions"}
    if keys - allowed:
        return "unknown key"
    if cert.get("wrenchkit_certificate") in (1, 2, 3) and cert.get("property") in ("motion", "hold"):
        try:
            return (verify_motion if cert["property"] == "motion" else verify_hold)(scene, cert)
        except (ValueError, KeyError, TypeError) as e:
            return f"malformed: {e}"
    if cert.get("wrenchkit_certificate") != 1 or cert.get("property") not in PROPERTIES:
        return "header"
    friction = cert["property"] != "form_closure"
    equilibrium = cert["property"] == "equilibrium"
    gens = [generators(c, friction) for c in scene.get("contacts", [])]
    load = load_wrench(scene) if equilibrium else (F(0), F(0), F(0))
    try:
        if cert["holds"] is True:
            wanted = {"wrenchkit_certificate", "property", "holds", "combination"}
            if keys != (wanted if equilibrium else wanted | {"independent"}):
                return "keys"
            if load is None:
                return "no load"

            def gen(ref):
                i, e = ref["contact"], ref["edge"]
                if not (type(i) is int and 0 <= i < len(gens)):
                    return None
                return gens[i].get(e)

            terms = cert["combination"]
            if not terms and not equilibrium:
                return "empty"
            if any(gen(t) is None for t in terms) or any(gen(r) is None for r in cert.get("independent", [])):
                return "reference"
            names = [(t["contact"], t["edge"]) for t in terms]
            if len(set(names)) != len(names):
                return "duplicate"
            weights = [rational(t["weight"]) for t in terms]
            if any(w <= 0 for w in weights):
                return "weight"
            if any(sum(w * gen(t)[k] for w, t in zip(weights, terms)) + load[k] != 0 for k in range(3)):
                return "sum"
            if equilibrium:
                return None
            ind = cert["independent"]
            if len(ind) != 3 or any((r["contact"], r["edge"]) not in names for r in ind):
                return "independent"
            if det3(*(gen(r) for r in ind)) == 0:
                return "determinant"
            return None
        if keys - {"reading"} != {"wrenchkit_certificate", "property", "holds", "twist"}:
            return "keys"
        if load is None:
            return "no load"
        vx, vy, w = (rational(v) for v in cert["twist"])
        if (vx, vy, w) == (0, 0, 0):
            return "zero twist"
        for g in (g for c in gens for g in c.values()):
            if vx * g[0] + vy * g[1] + w * g[2] < 0:
                return "power"
        if equilibrium and vx * load[0] + vy * load[1] + w * load[2] <= 0:
            return "load power"
        if "reading" in cert:
            r = cert["reading"]
            label = "+" if w > 0 else "-" if w < 0 else "infinity"
            if r["label"] != label:
                return "label"
            if w != 0:
                if set(r) != {"label", "point"} or [rational(v) for v in r["point"]] != [-vy / w, vx / w]:
                    return "point"
            else:
                dx, dy = -vy, vx
                ex, ey = (rational(v) for v in r["direction"])
                if set(r) != {"label", "direction"} or dx * ey - dy * ex != 0 or dx * ex + dy * ey <= 0:
                    return "direction"
        return None
    except (ValueError, KeyError, TypeError) as e:
        return f"malformed: {e}"


# ----------------------------------------------------------------------------------------------
# Computed certificate: an uneven strictly positive combination of the triangle's six edges


def triangle_uneven():
    scene = SCENES["triangle_mu_1_10"]
    gens = [generators(c, True)[e] for c, e in ((scene["contacts"][i], e) for i, e in TRIANGLE_EDGES)]
    # Weights 1 sum to zero (each contact's left + right is 2n at p; the normals' wrenches sum to 0).
    # Add t times a null-space vector that moves weight between contact 0 and contact 1:
    # solve x0*g0L + x1*g0R + y*g1L = -g1R for (x0, x1, y), then v = (x0, x1, y, 1, 0, 0) is in the null space.
    A = [[gens[0][k], gens[1][k], gens[2][k], -gens[3][k]] for k in range(3)]
    for col in range(3):  # Gauss-Jordan on a 3x4 augmented matrix
        piv = next(r for r in range(col, 3) if A[r][col] != 0)
        A[col], A[piv] = A[piv], A[col]
        A[col] = [v / A[col][col] for v in A[col]]
        for r in range(3):
            if r != col:
                A[r] = [a - A[r][col] * b for a, b in zip(A[r], A[col])]
    null = [A[0][3], A[1][3], A[2][3], F(1), F(0), F(0)]
    weights = [1 + F(1, 3) * v for v in null]
    assert all(w > 0 for w in weights)
    assert all(sum(w * g[k] for w, g in zip(weights, gens)) == 0 for k in range(3))
    return positive("force_closure", comb(*[(c, e, str(w)) for (c, e), w in zip(TRIANGLE_EDGES, weights)]),
                    refs((0, "left"), (1, "right"), (2, "left")))


# ----------------------------------------------------------------------------------------------
# Computed equilibrium certificates: a small exact search over the friction edges (by Caratheodory,
# if -w_ext is in the cone of the edges it is in the cone of at most three of them)


def solve(columns, b):
    """The unique x with sum_j x_j columns[j] = b (columns independent), or None."""
    n = len(columns)
    A = [[columns[j][k] for j in range(n)] + [b[k]] for k in range(3)]
    for col in range(n):  # Gauss-Jordan on a 3 x (n+1) augmented matrix
        piv = next((r for r in range(col, 3) if A[r][col] != 0), None)
        if piv is None:
            return None
        A[col], A[piv] = A[piv], A[col]
        A[col] = [v / A[col][col] for v in A[col]]
        for r in range(3):
            if r != col:
                A[r] = [a - A[r][col] * c for a, c in zip(A[r], A[col])]
    if any(A[r][n] != 0 for r in range(n, 3)):
        return None
    return [A[r][n] for r in range(n)]


def balancing_weights(scene_name, use=lambda contact, edge: True, accept=lambda x: all(v > 0 for v in x)):
    """The first combination (fewest terms, then in scene order) of at most three friction edges
    allowed by `use` whose weights x satisfy accept(x) and sum_k x_k g_k = -w_ext."""
    scene = SCENES[scene_name]
    edges = [(i, e, g) for i, c in enumerate(scene["contacts"]) for e, g in generators(c, True).items() if use(i, e)]
    minus_load = tuple(-v for v in load_wrench(scene))
    for k in (1, 2, 3):
        for subset in itertools.combinations(edges, k):
            x = solve([g for _, _, g in subset], minus_load)
            if x is not None and accept(x):
                return comb(*[(i, e, str(v)) for (i, e, _), v in zip(subset, x)])
    raise AssertionError(f"no balancing weights for {scene_name}")


def computed(scene_name, desc):
    """(expected, certificate) of a table entry whose certificate (and maybe its expectation) is None."""
    gravity = "block_corner_mu_1_2_gravity"
    if (scene_name, desc) == ("triangle_mu_1_10", "force_uneven"):
        return "valid", triangle_uneven()
    if (scene_name, desc) == (gravity, "equilibrium"):  # the floor alone carries the weight
        return "valid", equilibrium_true(balancing_weights(gravity, lambda i, e: i in (0, 1)))
    if (scene_name, desc) == (gravity, "equilibrium_with_wall"):  # three edges, one of them on the wall
        return "valid", equilibrium_true(balancing_weights(gravity, lambda i, e: (i, e) in ((0, "left"), (1, "left"), (2, "left"))))
    if (scene_name, desc) == (gravity, "independent_present"):
        cert = equilibrium_true(balancing_weights(gravity, lambda i, e: i in (0, 1)))
        cert["independent"] = refs((0, "left"), (1, "right"), (0, "right"))
        return None, cert
    if (scene_name, desc) == (gravity, "negative_weight"):  # weights that do balance, but one is negative
        terms = balancing_weights(gravity, accept=lambda x: len(x) == 3 and 0 not in x and min(x) < 0)
        k, bad = next((k, u) for k, u in enumerate(terms) if F(u["weight"]) < 0)
        return f'invalid:weight|combination[{k}].weight: "{bad["weight"]}" is not strictly positive', equilibrium_true(terms)
    if (scene_name, desc) == (gravity, "hold_without_support"):  # equilibrium's weights, as a hold
        return "valid", hold(True, combination=balancing_weights(gravity, lambda i, e: i in (0, 1)))
    if (scene_name, desc) == (gravity, "hold_with_support_forces"):
        return None, hold(True, combination=balancing_weights(gravity, lambda i, e: i in (0, 1)), support_forces=[])
    if (scene_name, desc) == ("block_corner_mu_1_2_push", "equilibrium"):  # the wall alone
        return "valid", equilibrium_true(balancing_weights("block_corner_mu_1_2_push", lambda i, e: i in (2, 3)))
    if (scene_name, desc) == ("block_corner_mu_1_2_pull", "push_weights"):
        return None, equilibrium_true(balancing_weights("block_corner_mu_1_2_push", lambda i, e: i in (2, 3)))
    raise KeyError((scene_name, desc))


# ----------------------------------------------------------------------------------------------
# Writing


def dump(obj, indent=""):
    """JSON with one contact / term per line: readable and diff-friendly."""
    if isinstance(obj, dict) and indent == "":
        inner = [f'  {json.dumps(k)}: {dump(v, "  ")}' for k, v in obj.items()]
        return "{\n" + ",\n".join(inner) + "\n}\n"
    if isinstance(obj, list) and obj and all(isinstance(x, dict) for x in obj):
        return "[\n" + ",\n".join(indent + "  " + json.dumps(x) for x in obj) + "\n" + indent + "]"
    return json.dumps(obj)


def main():
    for name in os.listdir(HERE):
        if name.endswith(".json"):
            os.remove(os.path.join(HERE, name))
    for name, scene in SCENES.items():
        with open(os.path.join(HERE, f"{name}.scene.json"), "w") as f:
            f.write(dump(scene))
    failures = 0
    reasons = []
    for scene_name, desc, expected, cert in CERTS:
        if cert is None:
            exp, cert = computed(scene_name, desc)
            expected = expected or exp
        kind = "valid" if expected == "valid" else "invalid"
        path = os.path.join(HERE, f"{scene_name}.{desc}.{kind}.json")
        with open(path, "w") as f:
            f.write(dump(cert))
        if kind == "invalid":
            reasons.append(f"{os.path.basename(path)}\t{expected.split('|', 1)[1]}\n")
        # read both files back from disk, exactly (numbers kept as text)
        load = lambda p: json.load(open(p), parse_float=str, parse_int=int)  # noqa: E731
        scene = load(os.path.join(HERE, f"{scene_name}.scene.json"))
        reason = verify(scene, load(path))
        want = None if kind == "valid" else expected[len("invalid:"):].split("|")[0]
        if not (reason == want or (want == "malformed" and reason and reason.startswith(want))):
            print(f"MISMATCH {os.path.basename(path)}: {reason or 'passes'}")
            failures += 1
        else:
            print(f"ok  {os.path.basename(path)}: {reason or 'passes'}")
    with open(os.path.join(HERE, "invalid-reasons.tsv"), "w") as f:
        f.write("# file<TAB>text that the checker's reason must contain (written by make_examples.py)\n")
        f.writelines(reasons)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
