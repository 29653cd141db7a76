"""The few words the starters write on their pages, in each language a calendar panel speaks.

A German calendar with English titles would look unfinished, so every text a starter puts on
a page comes from here, in the project's language. The texts are only a start: users edit them.
"""

from __future__ import annotations

from floatpage.model.calendar_month import LANGUAGES
from floatpage.model.calendar_month import month_name as panel_month_name

PHRASES = {
    "card_front": {
        "en": "Happy Birthday!", "de": "Alles Gute zum Geburtstag!", "fr": "Joyeux anniversaire !",
        "es": "¡Feliz cumpleaños!", "it": "Buon compleanno!", "pt": "Feliz aniversário!",
        "nl": "Gefeliciteerd!",
    },
    "card_message": {
        "en": "Wishing you a year full of sunshine, flowers and good friends.",
        "de": "Ich wünsche dir ein Jahr voller Sonnenschein, Blumen und guter Freunde.",
        "fr": "Je te souhaite une année pleine de soleil, de fleurs et de bons amis.",
        "es": "Te deseo un año lleno de sol, flores y buenos amigos.",
        "it": "Ti auguro un anno pieno di sole, fiori e buoni amici.",
        "pt": "Desejo-te um ano cheio de sol, flores e bons amigos.",
        "nl": "Ik wens je een jaar vol zon, bloemen en goede vrienden.",
    },
    "card_signature": {
        "en": "With love, Sam", "de": "Alles Liebe, Sam", "fr": "Avec tendresse, Sam",
        "es": "Con cariño, Sam", "it": "Con affetto, Sam", "pt": "Com carinho, Sam", "nl": "Liefs, Sam",
    },
    "album_title": {
        "en": "Our photo album", "de": "Unser Fotoalbum", "fr": "Notre album photo",
        "es": "Nuestro álbum de fotos", "it": "Il nostro album", "pt": "O nosso álbum",
        "nl": "Ons fotoalbum",
    },
    "flyer_title": {lang: "The Corner Shop" for lang in LANGUAGES} | {
        "de": "Der Eckladen", "fr": "L'Épicerie du Coin", "es": "La Tienda de la Esquina",
        "it": "La Bottega all'Angolo", "pt": "A Mercearia da Esquina", "nl": "De Hoekwinkel",
    },
    "flyer_subtitle": {
        "en": "Fresh offers this week", "de": "Frische Angebote dieser Woche",
        "fr": "Les offres fraîches de la semaine", "es": "Ofertas frescas de la semana",
        "it": "Offerte fresche della settimana", "pt": "Ofertas frescas da semana",
        "nl": "Verse aanbiedingen van deze week",
    },
    "flyer_footer": {
        "en": "Open every day 8:00–20:00 · 12 Market Street",
        "de": "Täglich geöffnet 8:00–20:00 · Marktstraße 12",
        "fr": "Ouvert tous les jours 8h–20h · 12 rue du Marché",
        "es": "Abierto todos los días 8:00–20:00 · Calle del Mercado 12",
        "it": "Aperto tutti i giorni 8:00–20:00 · Via del Mercato 12",
        "pt": "Aberto todos os dias 8:00–20:00 · Rua do Mercado 12",
        "nl": "Elke dag open 8:00–20:00 · Marktstraat 12",
    },
}

PRODUCTS = {  # bundled product picture stem -> name in each language
    "apples": {"en": "Apples", "de": "Äpfel", "fr": "Pommes", "es": "Manzanas", "it": "Mele",
               "pt": "Maçãs", "nl": "Appels"},
    "lemons": {"en": "Lemons", "de": "Zitronen", "fr": "Citrons", "es": "Limones", "it": "Limoni",
               "pt": "Limões", "nl": "Citroenen"},
    "coffee-mug": {"en": "Coffee mug", "de": "Kaffeebecher", "fr": "Tasse à café", "es": "Taza de café",
                   "it": "Tazza da caffè", "pt": "Caneca de café", "nl": "Koffiemok"},
    "potted-plant": {"en": "Potted plant", "de": "Topfpflanze", "fr": "Plante en pot",
                     "es": "Planta en maceta", "it": "Pianta in vaso", "pt": "Planta em vaso",
                     "nl": "Kamerplant"},
    "teapot": {"en": "Teapot", "de": "Teekanne", "fr": "Théière", "es": "Tetera", "it": "Teiera",
               "pt": "Bule de chá", "nl": "Theepot"},
    "sunflower": {"en": "Sunflowers", "de": "Sonnenblumen", "fr": "Tournesols", "es": "Girasoles",
                  "it": "Girasoli", "pt": "Girassóis", "nl": "Zonnebloemen"},
    "tulips": {"en": "Tulips", "de": "Tulpen", "fr": "Tulipes", "es": "Tulipanes", "it": "Tulipani",
               "pt": "Túlipas", "nl": "Tulpen"},
    "cupcake": {"en": "Cupcake", "de": "Cupcake", "fr": "Cupcake", "es": "Magdalena", "it": "Cupcake",
                "pt": "Queque", "nl": "Cupcake"},
}


def month_name(month: int, lang: str) -> str:
    """The month's name as the panel prints it, so the page title and the panel agree."""
    return panel_month_name(month, lang)


def phrase(key: str, lang: str) -> str:
    return PHRASES[key][lang]


def product_name(stem: str, lang: str) -> str:
    """A bundled product's name, or a user's file name made readable ("red_shoes" -> "Red shoes")."""
    if stem in PRODUCTS:
        return PRODUCTS[stem][lang]
    return readable(stem)


def readable(stem: str) -> str:
    """A caption from a file name: separators become spaces, first letter upper case."""
    words = stem.replace("_", " ").replace("-", " ").split()
    text = " ".join(words) or stem
    return text[:1].upper() + text[1:]


def price(cents: int, lang: str) -> str:
    """A price in euros the way the language writes it: €2.40, 2,40 €, € 2,40."""
    euros, rest = divmod(cents, 100)
    if lang == "en":
        return f"€{euros}.{rest:02d}"
    if lang == "nl":
        return f"€ {euros},{rest:02d}"
    return f"{euros},{rest:02d} €"
