"""What happens to findings after rules report them.

Traces that explain them, fingerprints that identify them across edits, inline
suppressions and baselines that silence them.
"""
