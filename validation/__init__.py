"""validation: demos, benchmarks, scenes and the report."""
