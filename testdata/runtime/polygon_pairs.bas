data p; 1, 2, 3
polygon p // expect-runtime-error: argument 1 (points) of polygon must hold at least two x, y pairs
