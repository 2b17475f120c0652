"""Control software of each of the five flavours, and legacy (one-digit) strings, for the tests."""

FLAVOUR_SOFTWARE = {
    "chocolate": "--fsm-config --nstates 2 --s0 11 --n0 1 --n0x0 0 --c0x0 10 --p0x0 0.5 --s1 10 --rwm1 5 "
                 "--n1 1 --n1x0 0 --c1x0 11 --p1x0 0.3",
    "tuttifrutti": "--fsm-config --nstates 2 --s0 20 --rwm0 30 --cle0 4 --n0 1 --n0x0 0 --c0x0 27 --p0x0 0.7 --l0x0 2 "
                   "--s1 28 --vel1 1 --cle1 5 --clr1 3 --n1 1 --n1x0 0 --c1x0 25 --p1x0 0.1",
    "coconut": "--fsm-config --nstates 2 --s0 30 --exp0 2 --mu0 2 --rho0 0.5 --n0 1 --n0x0 0 --c0x0 33 --p0x0 3 "
               "--w0x0 5 --s1 34 --att1 3 --exp1 1 --rwm1 10 --n1 1 --n1x0 0 --c1x0 35 --p1x0 0.2",
    "maple": "--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 0.27 --n01 5 --a01 44 "
             "--att01 4.93 --p01 0 --n1 0 --nchild1 2 --n10 6 --c10 42 --p10 0.5 --n11 5 --a11 40 --rwm11 20 --p11 0",
    "arlequin": "--fsm-config --nstates 2 --s0 50 --n0 1 --n0x0 0 --c0x0 53 --p0x0 2 --w0x0 3 --s1 54 --n1 1 "
                "--n1x0 0 --c1x0 55 --p1x0 0.1",
}

LEGACY = {
    "chocolate": "--fsm-config --nstates 2 --s0 1 --n0 1 --n0x0 0 --c0x0 0 --p0x0 0.5 --s1 0 --rwm1 5 --n1 1 "
                 "--n1x0 0 --c1x0 1 --p1x0 0.3",
    "tuttifrutti": "--fsm-config --nstates 2 --s0 0 --rwm0 30 --cle0 4 --n0 1 --n0x0 0 --c0x0 7 --p0x0 0.7 --l0x0 2 "
                   "--s1 1 --cle1 5 --n1 1 --n1x0 0 --c1x0 5 --p1x0 0.1",
    "maple": "--bt-config --rootnode 0 --nchildsroot 2 --n0 0 --nc0 1 --c0x0 0 --p0x0 0.27 --a0 4 --att0 4.93 "
             "--n1 0 --nc1 1 --c1x0 2 --p1x0 0.5 --a1 0 --rwm1 20",
}

# A mission each flavour was made for (the parity test runs each there and on aac).
FLAVOUR_MISSION = {"chocolate": "aac", "tuttifrutti": "tutti-foraging", "coconut": "coconut-foraging", "maple": "foraging",
                   "arlequin": "aggregation"}
