# pen (Python turtle peer): 100,000 pen-down segments with the screen updates off.
import time
import turtle

t0 = time.perf_counter()
screen = turtle.Screen()
screen.tracer(0, 0)
t = turtle.Turtle()
t.hideturtle()
t.speed(0)
t.pendown()
for i in range(1, 100001):
    t.forward(1 + (i % 40))
    t.right(91)
screen.update()
print(round(t.xcor()), round(t.ycor()))
print(f"turtle seconds {time.perf_counter() - t0:.3f}")
