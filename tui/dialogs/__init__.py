"""Modal dialogs: each is a ModalScreen[T] that dismisses with its answer (None = cancelled)."""

from tui.dialogs.choice import ChoiceDialog
from tui.dialogs.form import Field, FormDialog
from tui.dialogs.help import HelpScreen
from tui.dialogs.picture import PictureDialog

__all__ = ["ChoiceDialog", "Field", "FormDialog", "HelpScreen", "PictureDialog"]
