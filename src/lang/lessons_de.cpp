// The built-in lessons in German: lang/lessons_en.cpp's, step for step (a test holds them to it).
#include "lang/lang.hpp"

namespace noneuclid::lang {

extern const LessonText kLessons_de[] = {
    {"curvature", R"(title = "Was Krümmung ist"
about = "K von -1 bis +1: dasselbe Gitter auf einer Kugel, einer Ebene und einem Sattel"

[[step]]
caption = "Das ist flacher Raum: K = 0. Die Linien des Gitters sind gerade, seine Quadrate sind Quadrate."
scene = "kiosk"
curvature = 0
question = "Wie viele Quadrate treffen sich an jeder Ecke des Gitters?"
seconds = 20

[[step]]
caption = "Halte K+ (die Taste + oder den Knopf K+). Der Raum krümmt sich wie eine Kugel: das Gitter wölbt sich."
curvature = 0
done = "curvature above 0.9"
seconds = 40

[[step]]
caption = "Bei K = +1 ist der ganze Kreis eine Kugel, von innen gesehen. Halte jetzt K- bis unter null."
curvature = 1
done = "curvature below -0.9"
seconds = 40

[[step]]
caption = "Bei K = -1 ist der Raum hyperbolisch: weit draußen ist mehr Platz, und die Linien laufen auseinander."
curvature = -1
question = "Wo sieht das Gitter am meisten gestaucht aus, und warum?"
seconds = 20
)"},
    {"lines", R"(title = "Gerade Linien und Parallelen"
about = "Linien, die parallel beginnen, treffen sich, bleiben im Abstand oder laufen auseinander, wie K es sagt"

[[step]]
caption = "Zwei gerade Linien beginnen nebeneinander, rechtwinklig zur selben Linie."
scene = "fig2"
curvature = 0
question = "Treffen sie sich auf flachem Papier jemals?"
seconds = 15

[[step]]
caption = "Auf einer Kugel (K = +1) treffen sich dieselben zwei Linien, wie Meridiane an einem Pol."
curvature = 1
question = "Wie weit entfernt treffen sie sich?"
seconds = 15

[[step]]
caption = "Im hyperbolischen Raum (K = -1) laufen sie auseinander: keine Parallele behält denselben Abstand."
curvature = -1
question = "Zeichne die zwei Linien bei K = -1."
seconds = 15

[[step]]
caption = "Verändere K selbst mit K+ und K- und beobachte, wo sich die Linien kreuzen."
curvature = 0
done = "curvature above 0.9"
seconds = 45
)"},
    {"triangles", R"(title = "Dreiecke und Kreise"
about = "Die Winkel eines Dreiecks ergeben mehr oder weniger als 180 Grad, und der Umfang eines Kreises ist nicht 2 pi r"

[[step]]
caption = "Ein Dreieck mit gemessenen Winkeln. Bei K = 0 ergeben sie zusammen 180 Grad."
scene = "measure"
curvature = 0
question = "Schreibe die drei Winkel und ihre Summe auf."
seconds = 20

[[step]]
caption = "Halte jetzt K+ bis +1: dasselbe Dreieck auf einer Kugel. Beobachte die Winkelsumme."
curvature = 0
done = "curvature above 0.9"
question = "Wie groß ist die Winkelsumme bei K = +1? Mehr oder weniger als 180?"
question_curvature = 1
seconds = 45

[[step]]
caption = "Und halte K- bis -1: auf einem Sattel werden die Winkel kleiner."
curvature = 1
done = "curvature below -0.9"
question = "Wie groß ist die Winkelsumme bei K = -1?"
question_curvature = -1
seconds = 45

[[step]]
caption = "Drücke M für den Kreis: sein Umfang gegen 2 pi r. Fliege das Schiff und markiere mit Feuer ein eigenes Dreieck."
curvature = 0.5
question = "Fliege ein Dreieck: wie groß ist seine Winkelsumme, und wie wächst sie mit der Fläche des Dreiecks?"
seconds = 60
)"},
    {"game", R"(title = "Das Spiel im gekrümmten Raum"
about = "Asteroids, wobei sich die Krümmung mit jeder Stufe ändert"

[[step]]
caption = "Feuer startet das Spiel. Asteroiden fliegen geradeaus, entlang Geodäten: sieh, wie sie sich biegen, wenn K sich ändert."
scene = "asteroids"
question = "Auf welcher Stufe ist das Zielen am schwersten, und warum?"
done = "score 100"
seconds = 120

[[step]]
caption = "Gut gemacht. Bei K = +1 kommt ein Geschoss, das weit genug fliegt, von der anderen Seite zurück."
curvature = 1
question = "Warum kommt ein Geschoss auf einer Kugel zurück?"
seconds = 60
)"},
};
extern const int kLessonsCount_de = sizeof kLessons_de / sizeof kLessons_de[0];

}  // namespace noneuclid::lang
