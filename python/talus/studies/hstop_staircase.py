"""The walk of Weinhart et al. 2012's h_stop search (Sect. 6), apart from running its cases: from
(H0, theta0) the angle rises by 1 deg until the layer flows; then the height rises by 2 if the flow
arrested, else the angle falls by 0.5 deg. chute_hstop.py runs it on the engine; the validation's
resolution study walks it on outcomes drawn from a known curve. No imports, so that it loads
without the built package."""


class Staircase:
    """One lambda's search: `case` is the one whose result is needed next."""

    def __init__(self, lam, h0, theta0, h_max, theta_min, max_cases):
        self.lam, self.h_max, self.theta_min, self.max_cases = lam, h_max, theta_min, max_cases
        self.case = (lam, h0, theta0)
        self.rising = True  # still raising the angle until the first flow
        self.visited = []

    def successors(self, case=None):
        """(next if arrested, next if flowing) after `case`."""
        lam, H, th = case or self.case
        if self.rising:
            return (lam, H, th + 1.0), (lam, H, th - 0.5)
        return (lam, H + 2, th), (lam, H, th - 0.5)

    def advance(self, arrested):
        self.visited.append((self.case, arrested))
        on_arrest, on_flow = self.successors()
        if not arrested:
            self.rising = False
        self.case = on_arrest if arrested else on_flow
        lam, H, th = self.case
        if H > self.h_max or th < self.theta_min or th > 60 or len(self.visited) >= self.max_cases:
            self.case = None
