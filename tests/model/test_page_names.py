"""Pages the editor named follow their place; the user's names and item ids are never taken."""

from floatpage.model.document import Page
from floatpage.model.page_names import named_by_place, rename_by_place


def pages(*names: str) -> list[Page]:
    return [Page(id=name) for name in names]


def test_the_editors_names_follow_their_place_and_the_users_stay():
    album = pages("page-1", "cover", "page-3", "page-9")
    followers = named_by_place(album)  # page-1 and page-3 (page-9 at place 4 is the user's)
    album.insert(1, Page(id="new"))
    followers.add(id(album[1]))
    renamed = rename_by_place(album, followers, set())
    assert [page.id for page in album] == ["page-1", "page-2", "cover", "page-4", "page-9"]
    assert renamed == {"new": "page-2", "page-3": "page-4"}


def test_a_name_an_item_or_a_users_page_holds_is_not_taken():
    book = pages("page-1", "page-2")
    followers = named_by_place(book)
    book.insert(1, Page(id="new"))
    followers.add(id(book[1]))
    rename_by_place(book, followers, {"page-2"})  # an item is called page-2
    names = [page.id for page in book]
    assert names[0] == "page-1" and "page-2" not in names and len(set(names)) == 3
