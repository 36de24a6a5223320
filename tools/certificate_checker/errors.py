"""How the checker says no: Rejected names the claim that fails and why
(exit 1); Unreadable is an input it cannot read or a format it does not
cover (exit 2)."""


class Rejected(Exception):
    def __init__(self, claim, reason):
        super().__init__(claim + ": " + reason)
        self.claim, self.reason = claim, reason


class Unreadable(Exception):
    pass


def reject(claim, reason):
    raise Rejected(claim, reason)
