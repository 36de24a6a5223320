"""certificate_checker: the second, independent checker of eccd's exact
certificates ("eccd-certificate/2", 2D and 3D), in Python with the standard
library only (fractions, json). It shares no code with eccd's prover; an
auditor reads it in an hour (docs/checking.md). tools/check_certificate.py is
its command line; check.check runs the claims in order."""
