// The built-in lessons in French: lang/lessons_en.cpp's, step for step (a test holds them to it).
#include "lang/lang.hpp"

namespace noneuclid::lang {

extern const LessonText kLessons_fr[] = {
    {"curvature", R"(title = "Ce qu'est la courbure"
about = "K de -1 à +1 : la même grille sur une sphère, un plan et une selle"

[[step]]
caption = "Voici l'espace plat : K = 0. Les lignes de la grille sont droites et ses carrés sont des carrés."
scene = "kiosk"
curvature = 0
question = "Combien de carrés se rencontrent à chaque coin de la grille ?"
seconds = 20

[[step]]
caption = "Maintenez K+ (la touche + ou le bouton K+). L'espace se courbe comme une sphère : la grille se bombe."
curvature = 0
done = "curvature above 0.9"
seconds = 40

[[step]]
caption = "À K = +1 le cercle entier est une sphère vue de l'intérieur. Maintenez maintenant K- au-delà de zéro."
curvature = 1
done = "curvature below -0.9"
seconds = 40

[[step]]
caption = "À K = -1 l'espace est hyperbolique : il y a plus de place au loin, et les lignes s'écartent en éventail."
curvature = -1
question = "Où la grille paraît-elle la plus écrasée, et pourquoi ?"
seconds = 20
)"},
    {"lines", R"(title = "Lignes droites et parallèles"
about = "Des lignes qui partent parallèles se rencontrent, restent à distance ou s'écartent, selon K"

[[step]]
caption = "Deux lignes droites partent côte à côte, à angle droit sur la même ligne."
scene = "fig2"
curvature = 0
question = "Sur une feuille plate, se rencontrent-elles jamais ?"
seconds = 15

[[step]]
caption = "Sur une sphère (K = +1) les deux mêmes lignes se rencontrent, comme les méridiens à un pôle."
curvature = 1
question = "À quelle distance se rencontrent-elles ?"
seconds = 15

[[step]]
caption = "Dans l'espace hyperbolique (K = -1) elles s'écartent : aucune parallèle ne reste à la même distance."
curvature = -1
question = "Dessinez les deux lignes à K = -1."
seconds = 15

[[step]]
caption = "Faites varier K vous-même avec K+ et K- et regardez où les lignes se croisent."
curvature = 0
done = "curvature above 0.9"
seconds = 45
)"},
    {"triangles", R"(title = "Triangles et cercles"
about = "La somme des angles d'un triangle dépasse 180 degrés ou n'y arrive pas, et un cercle ne mesure pas 2 pi r"

[[step]]
caption = "Un triangle dont les angles sont mesurés. À K = 0 leur somme fait 180 degrés."
scene = "measure"
curvature = 0
question = "Notez les trois angles et leur somme."
seconds = 20

[[step]]
caption = "Maintenez K+ jusqu'à +1 : le même triangle sur une sphère. Regardez la somme des angles."
curvature = 0
done = "curvature above 0.9"
question = "Quelle est la somme des angles à K = +1 ? Plus ou moins que 180 ?"
question_curvature = 1
seconds = 45

[[step]]
caption = "Et maintenez K- jusqu'à -1 : sur une selle les angles rétrécissent."
curvature = 1
done = "curvature below -0.9"
question = "Quelle est la somme des angles à K = -1 ?"
question_curvature = -1
seconds = 45

[[step]]
caption = "Appuyez sur M pour le cercle : sa longueur face à 2 pi r. Pilotez le vaisseau, marquez un triangle à vous avec feu."
curvature = 0.5
question = "Tracez un triangle en vol : quelle est la somme de ses angles, et comment croît-elle avec son aire ?"
seconds = 60
)"},
    {"game", R"(title = "Le jeu dans l'espace courbe"
about = "Asteroids, où la courbure change à chaque niveau"

[[step]]
caption = "Feu lance la partie. Les astéroïdes volent tout droit, le long de géodésiques : regardez-les se courber quand K change."
scene = "asteroids"
question = "À quel niveau est-il le plus difficile de viser, et pourquoi ?"
done = "score 100"
seconds = 120

[[step]]
caption = "Bravo. À K = +1 un tir qui va assez loin revient de l'autre côté."
curvature = 1
question = "Pourquoi un tir revient-il sur une sphère ?"
seconds = 60
)"},
};
extern const int kLessonsCount_fr = sizeof kLessons_fr / sizeof kLessons_fr[0];

}  // namespace noneuclid::lang
