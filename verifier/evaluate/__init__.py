"""The evaluator: IR in, launch graph out (``runner.evaluate``; semantics in ``walker``)."""
