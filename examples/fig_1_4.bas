rLocate 400,300
