rLocate 400,300  
rSpeed 5
rForward 120  
rTurn 90
