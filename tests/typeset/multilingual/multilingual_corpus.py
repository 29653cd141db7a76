"""A multilingual corpus: greetings and phrases in many scripts, combining marks, every
kind of space, emoji and mixed directions. Each entry is (group, text).

Written for floatpage's tests; phrases are common greetings and words, not quotations.
"""

from __future__ import annotations

import unicodedata

LATIN = [
    "Happy birthday!", "Joyeux anniversaire, Chloé!", "¡Feliz cumpleaños, señor Muñoz!",
    "Alles Gute zum Geburtstag, Jürgen", "Grüße aus Köln", "Wszystkiego najlepszego, Łukasz",
    "Všechno nejlepší, Jiří", "Boldog születésnapot, Ödön", "Til hamingju með afmælið, Þórður",
    "Gratulerer med dagen, Åse og Ørjan", "Mutlu yıllar, İpek ve Işık", "Chúc mừng sinh nhật",
    "La mulți ani, Ștefan și Țepeș", "Sretan rođendan, Đurđa", "Daug laimės, Žygimantas",
    "Palju õnne, Õie", "Feliĉan naskiĝtagon", "Pen-blwydd hapus, Siân", "Ŵ ŷ ẅ ẃ",
    "Ǆ ǅ ǆ Ǉ ǈ ǉ", "Ɛwe Ɔkɔ ŋ ɖ", "Hawaiʻi ʻōlelo", "façade naïve coöperate",
    "ß ẞ æ Æ œ Œ ð Þ", "ﬁne ﬂour ﬀ ﬃ", "Dvořák Čapek Šíma", "Ångström ≈ 0.1 nm",
]
GREEK_CYRILLIC = [
    "Χρόνια πολλά!", "Καλημέρα κόσμε", "Ελληνικά: ά έ ή ί ό ύ ώ ϊ ϋ ΐ ΰ", "ἄνθρωπος ὁ ἀγαθός",
    "С днём рождения!", "Поздравляю, Юрий Ёлкин", "З днем народження, Їжачок Ґава",
    "Среќен роденден, Ѓорѓи", "Срећан рођендан, Ђорђе Џаковић", "Са днём нараджэння, Ўладзіслаў",
    "Туған күнің құтты болсын", "Төрсөн өдрийн мэнд", "Щастливо, Ъгъл и Ѣ",
    "Азбука: абвгдеёжзийклмнопрстуфхцчшщъыьэюя",
]
CJK = [
    "生日快乐", "新年快乐，万事如意", "祝你生日快樂", "お誕生日おめでとうございます",
    "ひらがな カタカナ 漢字", "생일 축하합니다", "새해 복 많이 받으세요", "謹賀新年　令和九年",
    "中文 and English mixed", "東京タワー 333m", "ｆｕｌｌｗｉｄｔｈ ＡＢＣ １２３", "半角ｶﾀｶﾅ",
    "一二三四五六七八九十", "「引用」『二重』【括弧】", "ㄅㄆㄇㄈ 注音", "𠀀 𠀁 𪚥 extension B",
]
RTL = [
    "عيد ميلاد سعيد", "كل عام وأنتم بخير", "مرحبا بالعالم", "السلام عليكم",
    "عيد ميلاد سعيد 2027", "الساعة ١٢:٣٠", "تولدت مبارک", "سالگرد ازدواج مبارک ۱۴۰۶",
    "سالگرہ مبارک", "יום הולדת שמח", "שנה טובה ומתוקה", "מזל טוב!", "חג שמח 2027",
    "שָׁלוֹם עֲלֵיכֶם", "بِسْمِ ٱللَّٰهِ", "ܫܠܡܐ ܥܠܡܐ", "ހުވަނދު",
]
MIXED = [
    "Happy birthday — عيد ميلاد سعيد!", "Party at 8 pm / الحفلة الساعة 8 مساءً",
    "Tel Aviv תל אביב 2027", "Price: 120 ₪ מחיר", "العدد 3.14 تقريبا", "abc אבג def",
    "אבג abc דהו", "«مرحبا» said Ali", "Room 12B — غرفة 12", "Email: a@b.c — البريد",
    "(قوس) [brackets]", "שלום, world!", "Love ❤ حب ❤ אהבה", "2027-11-24 תאריך",
    "Hi 你好 مرحبا שלום नमस्ते", "ABC ١٢٣ 123 ۱۲۳",
]
INDIC = [
    "जन्मदिन मुबारक", "नमस्ते दुनिया", "क्षत्रिय त्र ज्ञ श्र", "हिन्दी में शुभकामनाएँ",
    "वाढदिवसाच्या हार्दिक शुभेच्छा", "जन्मदिनको शुभकामना", "শুভ জন্মদিন", "নমস্কার বাংলা",
    "பிறந்தநாள் வாழ்த்துக்கள்", "வணக்கம்", "పుట్టినరోజు శుభాకాంక్షలు", "ಹುಟ್ಟುಹಬ್ಬದ ಶುಭಾಶಯಗಳು",
    "ജന്മദിനാശംസകൾ", "જન્મદિવસની શુભકામનાઓ", "ਜਨਮਦਿਨ ਮੁਬਾਰਕ", "ଜନ୍ମଦିନର ଶୁଭେଚ୍ଛା",
    "සුබ උපන්දිනයක්", "संस्कृतम् ॐ ।", "१२३४५ ৬৭৮৯০",
]
SOUTHEAST_AND_OTHER = [
    "สุขสันต์วันเกิด", "สวัสดีครับ", "ภาษาไทย ๑๒๓", "ສຸກສັນວັນເກີດ", "រីករាយថ្ងៃកំណើត",
    "မွေးနေ့ မင်္ဂလာပါ", "გილოცავ დაბადების დღეს", "Ծնունդդ շնորհավոր", "መልካም ልደት",
    "ཚེས་པ་བཀྲ་ཤིས།", "ᏣᎳᎩ ᎦᏬᏂᎯᏍᏗ", "ᐊᐃᓐᖓᐃ", "ᠮᠣᠩᠭᠣᠯ", "ⵜⴰⵎⴰⵣⵉⵖⵜ", "Ꭰ Ꭱ Ꭲ",
]
EMOJI = [
    "Party 🎉", "🎂🎈🎁", "Love ❤️ you", "👍🏽 thumbs", "👨‍👩‍👧‍👦 family", "🇩🇪 🇯🇵 flags",
    "☀️ sunny ☔ rain", "😀😃😄😁", "🏳️‍🌈 pride", "Cheers 🥂 2027", "✨ sparkle ✨", "🐱 cat 🐶 dog",
    "⭐ ★ ☆", "✓ ✔ ✗ ✘", "♠ ♥ ♦ ♣", "☺ ☹ ☻",
]
SYMBOLS = [
    "€ £ ¥ ₹ ₽ ₩ ₺ ₿", "→ ← ↑ ↓ ↔ ⇒", "∑ ∫ √ ∞ ≠ ≤ ≥", "½ ⅓ ¼ ⅛ ¾", "№ ™ © ® ℗ ℠",
    "° ′ ″ ‰ ‱", "♩ ♪ ♫ ♬", "① ② ③ ⑩", "Ⅰ Ⅱ Ⅲ Ⅳ Ⅻ", "•·‣⁃∙", "„Anführung“ «guillemets» ‹›",
    "‘single’ “double”", "… — – ‒ ―", "§ ¶ † ‡", "⌘ ⌥ ⇧ ⏎", "▲ ▼ ◆ ● ■ □",
]
MARKS = [
    "i\u0307", "I\u0307stanbul i\u0307", "Z\u0302", "Z\u0302\u0303",
    "Z\u0351\u0358\u0302\u0303\u0304\u0306\u0308\u030a\u030b\u0327\u0328",
    "H\u0336e\u0336l\u0336l\u0336o\u0336", "e\u0301 decomposed", "a\u0308o\u0308u\u0308",
    "n\u0303 n\u0303a\u0303", "q\u0307 x\u0323 w\u0327", "Q\u0300 J\u0301 K\u0302",
    "z\u0361s t\u035ch", "a\u20dd b\u20de", "1\u20e3 #\u20e3", "o\u0338 =\u0338",
    "Z\u0300\u0301\u0302\u0303\u0304\u0305\u0306\u0307\u0308\u0309\u030a\u030b\u030c\u030d"
    "\u030e\u030f\u0310\u0311\u0312\u0313\u0314",
    "T\u0316\u0317\u0318\u0319h\u031a\u031b\u031ce\u031d\u031e\u031f", "ǘ ǚ ǜ ṩ ḗ",
    "Ạ ạ Ậ ậ Ặ ặ", "L\u0325 m\u0325", "ŋ\u0301 ɔ\u0300 ɛ\u0302",
]
SPACE_CHARS = [chr(c) for c in (0x00A0, 0x1680, *range(0x2000, 0x200B), 0x202F, 0x205F, 0x3000)]
SPACES = [f"word{space}word" for space in SPACE_CHARS] + [
    "10\u2009000", "1\u202f000\u202f000", "tab\tand  double", "zero\u200bwidth", "soft\u00adhyphen",
    "join\u200dnon\u200cjoin", "ideographic\u3000space", "ogham\u1680space", "bom\ufeffhere",
    "rlm\u200fhere lrm\u200ehere",
]


def marks_systematically() -> list[str]:
    """Each ASCII letter with one accent that Latin fonts carry precomposed or as a mark."""
    accents = "\u0300\u0301\u0302\u0303\u0308\u030c\u0327"
    letters = "AEIOUYZaeiouyzCcGgNnSsQqXx"
    return [f"{letter}{accent}{letter.lower()}" for letter in letters for accent in accents[:2]]


# Written in a later hostile pass (none of them was in the lists above): more Indic scripts
# with their conjuncts, South-East Asian and other alphabets, right-to-left text in brackets
# with numbers, marks on CJK, variation selectors, controls, invisible characters, U+FFFD
# (which stopped LuaLaTeX) and TeX's own characters beside Arabic.
MORE_SCRIPTS = [
    "আমি বাংলায় গান গাই", "ক্ষ জ্ঞ ন্ত্র", "தமிழ் நாடு ஸ்ரீ க்ஷ", "తెలుగు భాష క్ష్మ",
    "ગુજરાતી ભાષા શ્ર", "ਪੰਜਾਬੀ ਗੁਰਮੁਖੀ ੴ", "ಕನ್ನಡ ಭಾಷೆ ಕ್ಷ", "മലയാളം ഭാഷ ന്റെ",
    "සිංහල භාෂාව ශ්‍රී", "ភាសាខ្មែរ ស្រី", "ພາສາລາວ ສະບາຍດີ", "မြန်မာဘာသာ ကျွန်ုပ်",
    "ქართული ენა", "Հայերեն լեզու", "ግዕዝ ፊደል ሰላም", "क्‍ष", "ि",
]
MORE_MIXED = [
    "(مرحبا [123] abc)", "שלום (עולם) [1-2]", "{عربي} <English> 3.5%", "א) 1. ב) 2.",
    "السعر: ١٬٢٣٤٫٥٦ ر.س", "version 2.0 (הגרסה החדשה)", "«اقتباس (داخلي) هنا»",
    "−5 °C درجة", "\\relax مرحبا %$#&_{}~^", "文字\\par{}",
]
MORE_MARKS_AND_INVISIBLES = [
    "漢\u0301字\u0308", "か\u3099 は\u309a", "한\u0323글", "א\u05b0\u05b1\u05b2\u05b3\u05b4\u05b5\u05b6",
    "\u0301 leading mark", "İIıi ǰ", "Ä\u0304 ǟ", "𝐀𝐁𝐂 𝔄𝔅 𝕏", "Ⓐⓑ",
    "☺\ufe0f ☺\ufe0e text", "❤\ufe0e mono heart", "葛\U000E0100 variation", "a\ufe00b",
    "bell\u0007here", "esc\u001b[31mred", "null\u0000byte", "del\u007fchar", "c1\u0085next\u009bcsi",
    "tab\tnew\nline", "cr\rreturn", "vt\u000bff\u000c", "lone\ud800surrogate",
    "\ufeffBOM at start", "zero\u200bwidth\u200bspaces", "soft\u00adhy\u00adphen\u00ad",
    "line\u2028sep\u2029para", "bidi\u202eoverride\u202c end", "iso\u2066late\u2069 d",
    "\u061c alm \u200f rlm", "word\u2060joiner", "inv\u2062times", "\U000e0041 tag",
    "repl\ufffd", "\ufffd\ufffd5\ufffd",
]

GROUPS = {
    "latin": LATIN, "greek-cyrillic": GREEK_CYRILLIC, "cjk": CJK, "rtl": RTL, "mixed": MIXED,
    "indic": INDIC, "southeast-other": SOUTHEAST_AND_OTHER, "emoji": EMOJI, "symbols": SYMBOLS,
    "marks": MARKS + marks_systematically(), "spaces": SPACES,
    "more-scripts": MORE_SCRIPTS, "more-mixed": MORE_MIXED,
    "more-marks-invisibles": MORE_MARKS_AND_INVISIBLES,
}


def corpus() -> list[tuple[str, str]]:
    return [(group, text) for group, texts in GROUPS.items() for text in texts]


if __name__ == "__main__":
    for group, text in corpus():
        print(group, unicodedata.normalize("NFC", text))
