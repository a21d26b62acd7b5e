// The built-in lessons in English (docs/lessons.md), in the lesson file format itself, so that a
// teacher can copy one and change it: `noneuclid lesson NAME --print` writes it out. Every other
// language's lessons_<code>.cpp follows these step for step.
#include "lang/lang.hpp"

namespace noneuclid::lang {

extern const LessonText kLessons_en[] = {
    {"curvature", R"(title = "What curvature is"
about = "K from -1 to +1: the same grid on a sphere, a plane and a saddle"

[[step]]
caption = "This is flat space: K = 0. The grid's lines are straight and its squares are squares."
scene = "kiosk"
curvature = 0
question = "How many squares meet at each corner of the grid?"
seconds = 20

[[step]]
caption = "Hold K+ (the + key, or the K+ button). Space curves like a sphere: the grid bulges."
curvature = 0
done = "curvature above 0.9"
seconds = 40

[[step]]
caption = "At K = +1 the whole circle is a sphere seen from inside. Now hold K- down past zero."
curvature = 1
done = "curvature below -0.9"
seconds = 40

[[step]]
caption = "At K = -1 space is hyperbolic: there is more room far out, and the lines fan apart."
curvature = -1
question = "Where does the grid look most squeezed, and why?"
seconds = 20
)"},
    {"lines", R"(title = "Straight lines and parallels"
about = "Lines that start parallel meet, stay apart or fly apart, as K says"

[[step]]
caption = "Two straight lines start side by side, at right angles to the same line."
scene = "fig2"
curvature = 0
question = "On flat paper, do they ever meet?"
seconds = 15

[[step]]
caption = "On a sphere (K = +1) the same two lines meet, like meridians at a pole."
curvature = 1
question = "How far along do they meet?"
seconds = 15

[[step]]
caption = "In hyperbolic space (K = -1) they fly apart: no parallel stays at the same distance."
curvature = -1
question = "Sketch the two lines at K = -1."
seconds = 15

[[step]]
caption = "Sweep K yourself with K+ and K- and watch where the lines cross."
curvature = 0
done = "curvature above 0.9"
seconds = 45
)"},
    {"triangles", R"(title = "Triangles and circles"
about = "A triangle's angles add up to more or less than 180 degrees, and a circle's length is not 2 pi r"

[[step]]
caption = "A triangle with its angles measured. At K = 0 they add up to 180 degrees."
scene = "measure"
curvature = 0
question = "Write down the three angles and their sum."
seconds = 20

[[step]]
caption = "Now hold K+ to +1: the same triangle on a sphere. Watch the angle sum."
curvature = 0
done = "curvature above 0.9"
question = "What is the angle sum at K = +1? Is it more or less than 180?"
question_curvature = 1
seconds = 45

[[step]]
caption = "And hold K- to -1: on a saddle the angles shrink."
curvature = 1
done = "curvature below -0.9"
question = "What is the angle sum at K = -1?"
question_curvature = -1
seconds = 45

[[step]]
caption = "Press M for the circle: its length against 2 pi r. Fly the ship, press fire to mark a triangle of your own."
curvature = 0.5
question = "Fly a triangle: what is its angle sum, and how does it grow with the triangle's area?"
seconds = 60
)"},
    {"game", R"(title = "The game in curved space"
about = "Asteroids where the curvature changes with each level"

[[step]]
caption = "Fire starts the game. Asteroids fly straight, along geodesics: watch them bend as K changes."
scene = "asteroids"
question = "At which level is it hardest to aim, and why?"
done = "score 100"
seconds = 120

[[step]]
caption = "Well done. At K = +1 a bullet that flies far enough comes back from the other side."
curvature = 1
question = "Why does a bullet come back on a sphere?"
seconds = 60
)"},
};
extern const int kLessonsCount_en = sizeof kLessons_en / sizeof kLessons_en[0];

}  // namespace noneuclid::lang
