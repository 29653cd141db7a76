"""Modal dialogs: each is a ModalScreen[T] that dismisses with its answer (None = cancelled)."""

from floatpage.tui.dialogs.choice import ChoiceDialog
from floatpage.tui.dialogs.form import Field, FormDialog
from floatpage.tui.dialogs.help import HelpScreen
from floatpage.tui.dialogs.picture import PictureDialog

__all__ = ["ChoiceDialog", "Field", "FormDialog", "HelpScreen", "PictureDialog"]
