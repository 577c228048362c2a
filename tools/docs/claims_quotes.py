"""The paper's own words for each row of the claims table (tools/docs/claims.py): a short quote of its
section 4 (French, as printed; [...] marks a cut) and an English gloss, keyed by the row's name. The
table writes them «quote» (gloss)."""

QUOTES = {
    # ---- 4.2.1, Fig. 11-14: circular pipe, constant g
    "zero": ("le manchon n'étant pas encore rentré en contact avec le tuyau la force de serrage est nulle",
             "zero force before contact"),
    "everywhere": ("le contact intervient sur toute la surface intérieure de la bague",
                   "contact over the whole inner surface at once"),
    "martensite": ("la bague reste dans un état martensitique", "the ring still martensite once in contact"),
    "linear": ("la force évolue de manière linéaire par rapport à la température", "then linear in T"),
    "inner": ("Le changement de phase s'initie sur la surface interne du manchon",
              "the reversion starts at the inner surface"),
    "jerks": ("la force de contact évolue donc par à coup", "jerky jumps while the ring reverts"),
    "sudden": ("le changement de phase intervient brutalement sur tout le manchon",
               "then the phase change sudden over the whole ring"),
    "constant": ("le matériau est entièrement dans un état austénitique et la force de serrage ne varie plus",
                 "constant once austenite"),
    "uniform": ("la force de serrage est uniforme", "final force uniform"),
    "radial": ("l'évolution de la contrainte (qui est radiale)", "the contact stress radial; 4.3: «toujours radiale»"),
    "bands": ("la température évolue par bande circulaire", "temperature in circular bands"),
    "iterations": ("Les nombres maxima d'itérations sont de l'ordre de 3 [...], de 4 pour l'algorithme D.C. et de 10 "
                   "pour l'algorithme de relaxation", "at most about 3 heat-phase, 4 DC, 10 PSOR iterations a step"),
    "grazing": ("En cas de contact affleurant le nombre d'itérations de la méthode de relaxation augmente",
                "grazing contact raises the PSOR count"),
    # ---- Fig. 15-16: single precision
    "single-differ": ("Les densités de force de serrage, données en trois points [...], diffèrent de manière importante",
                      "single precision: the three points' forces differ"),
    "single-local": ("le changement de phase se déclenche localement sans respecter la symétrie du problème",
                     "single precision: the phase change starts locally, breaking the symmetry"),
    "single-process": ("la propagation du changement de phase et ses effets locaux modifient le processus",
                       "single precision changes the process"),
    "double": ("la précision du maillage joue un rôle très important dans la qualité de la solution",
               "in double precision the three points' forces stay equal"),
    "no-contact": ("nous n'avons jamais rencontré ce type de difficulté pour des problèmes sans contact",
                   "single precision harmless without contact"),
    # ---- 4.2.2, Fig. 17-20: g = 2000 in contact
    "gvar-interface": ("il s'initialise au niveau de l'interface manchon-tuyau",
                       "g = 2000 in contact: the phase change starts at the interface"),
    "gvar-lower": ("(quand la température est inférieure à -30°C) la force de serrage est inférieure",
                   "force lower than with constant g below about -30 C"),
    "gvar-regular": ("par à-coup, de façon beaucoup plus régulière", "the rise much more regular than with constant g"),
    "gvar-maximum": ("elle a déjà atteint son niveau maximum au milieu de la phase de retour",
                     "the force at its maximum by the middle of the warming"),
    "gvar-equilibrium": ("accélère le retour à l'équilibre thermo-mécanique, la répartition de la température",
                         "the temperature evens out sooner"),
    "gvar-final": ("accélère [...] le processus de sertissage»; «répartis de façon uniforme et du même ordre",
                   "austenite sooner; final force uniform, same level"),
    # ---- 4.3, Fig. 21-24: off-centre ring
    "offset-phases": ("Un léger décentrage [...] n'a pas de conséquence sur le processus de sertissage",
                      "off-centre by 0.05 cm: the same four phases"),
    "offset-at-once": ("le contact intervient à cet instant en tout point", "off-centre: contact everywhere at once"),
    "offset-uniform": ("la force de serrage est uniforme. De plus, elle est du même ordre",
                       "force uniform and of the same level"),
    "offset-radial": ("des déplacements qui sont radiaux à tout instant du processus", "displacements radial"),
    # ---- 4.4.1, Fig. 25-28: elliptic pipe
    "ellipse-major": ("Le contact commence par intervenir suivant le grand axe", "contact starts on the major axis"),
    "ellipse-release": ("Avant que le contact ait lieu suivant le petit axe il y a relâchement suivant le grand axe",
                        "the major axis loosens before the minor axis touches"),
    "ellipse-five": ("cinq phases [...] des états successifs de contact et de relâchement",
                     "five phases: zero, touch and release near the major axis, linear, abrupt, constant"),
    "ellipse-uniform": ("quasiment uniforme. Elle est toutefois légèrement supérieure pour les nœuds du grand axe",
                        "nearly uniform, slightly higher on the major axis"),
    "ellipse-level": ("légèrement inférieure (de l'ordre de 10 %) aux cas précédents",
                      "about 10 % below the circular case"),
    # ---- 4.4.2, Fig. 29-32: elliptic pipe with friction
    "friction-major": ("Le contact s'initie sur le grand axe", "mu = 0.2: contact starts on the major axis"),
    "friction-lift": ("ce décollement ne concerne ici que des nœuds très proches du grand axe",
                      "mu = 0.2: lift-off only near the major axis"),
    "friction-five": ("cinq phases identiques au cas précédent", "mu = 0.2: the same five phases"),
    "friction-14": ("les forces diffèrent de 14 % entre le grand axe (nœud 300) et le petit axe (nœud 750)",
                    "final force 14 % higher on the major axis"),
    "friction-where": ("plus grande au niveau du grand axe [...], là où le frottement est plus important",
                       "force and friction larger at the major axis"),
    "friction-8": ("la force tangente est de l'ordre de 8 % de la force normale", "tangential force about 8 % of normal"),
    "friction-stick": ("tous les nœuds sont adhérents", "every node sticks"),
    # ---- 4.4.3, Fig. 33-36: random threshold
    "random-onset": ("A partir de cette valeur de la température [-25°C], le changement de phase a lieu",
                     "zero then linear, the phase change from about -25 C"),
    "random-less-abrupt": ("Le changement de phase intervient de manière moins brutale sur tout le manchon",
                           "less abrupt than with a homogeneous threshold"),
    "random-chaotic": ("La force de contact évolue dans ce cas de façon plus chaotique", "more chaotic, by jerks"),
    "random-peak": ("en passant par un pic (supérieur de 50 % à la valeur finale de la force de serrage)",
                    "a peak about 50 % above the final force"),
    "random-homogeneous": ("la température évolue de manière plus homogène", "temperature more homogeneous"),
    "random-minima": ("avec des minima au centre de la bague", "temperature minima mid-thickness"),
}


def said(key):
    """The table's cell for a row: «quote» (gloss)."""
    french, english = QUOTES[key]
    return f"«{french}» ({english})"
