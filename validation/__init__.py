"""validation: demos, benchmarks and (later, issue 6) scenes and the report."""
