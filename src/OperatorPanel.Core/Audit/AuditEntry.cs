using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Audit;

/// <summary>
/// One step of something the panel did to a PLC that changes it, a write or a STOP, as any record keeper takes it: the
/// write journal (<see cref="WriteJournal"/>), a historian, an export. An action's intent and its outcome share
/// <see cref="Id"/>; the intent is on record before the frame leaves the PC.
/// </summary>
/// <param name="Id">The action: its intent, outcome and any resolution at a later start share it.</param>
/// <param name="Step">Intent, outcome, or resolved at start (an intent whose program ended before its outcome).</param>
/// <param name="Action">A write or a STOP.</param>
/// <param name="At">When the step happened (UTC).</param>
/// <param name="User">Who asked: the OS user running the panel (DOMAIN\user on Windows).</param>
/// <param name="Port">The serial port of the station's bus ("COM3", "/dev/ttyUSB0"; "COM3 (demo)" for a simulated line).</param>
/// <param name="Station">The station written to or stopped.</param>
/// <param name="Target">The address written ("VD300"); null for a STOP.</param>
/// <param name="Symbol">The address's symbol in the project ("FillSetpoint"); null when it has none or none is known.</param>
/// <param name="OldValue">The value before, as the manual writes constants ("16#000003E7", "1"); "unknown" when never read; "RUN" for a STOP.</param>
/// <param name="NewValue">The value asked for ("16#0000002A"); "STOP" for a STOP.</param>
/// <param name="Outcome">For an outcome or resolution, what became of it ("confirmed", "not applied", "unknown", "applied"...); null for an intent.</param>
/// <param name="Detail">Why, when the outcome needs it (a cause, a read-back); null otherwise.</param>
public sealed record AuditEntry(
    Guid Id,
    AuditStep Step,
    AuditAction Action,
    DateTimeOffset At,
    string User,
    string Port,
    Station Station,
    string? Target,
    string? Symbol,
    string OldValue,
    string NewValue,
    string? Outcome = null,
    string? Detail = null)
{
    /// <summary>The step after this intent: same action, values and user, with its outcome.</summary>
    public AuditEntry Then(AuditStep step, DateTimeOffset at, string outcome, string? detail) =>
        this with { Step = step, At = at, Outcome = outcome, Detail = detail };

    /// <summary>"station 2 VD300 (FillSetpoint): 16#00000000 -> 16#000003E7", or "station 2: RUN -> STOP".</summary>
    public string Describe() => Target is null
        ? $"station {Station.Address}: {OldValue} -> {NewValue}"
        : $"station {Station.Address} {Target}{(Symbol is null ? string.Empty : $" ({Symbol})")}: {OldValue} -> {NewValue}";
}
