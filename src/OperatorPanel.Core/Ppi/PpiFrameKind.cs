namespace OperatorPanel.Core.Ppi;

/// <summary>
/// The four PROFIBUS FDL telegram formats PPI uses (EN 50170; docs/ppi.md section 2): the start delimiter names them.
/// </summary>
public enum PpiFrameKind
{
    /// <summary>SD2 16#68 LE LEr 16#68 DA SA FC data FCS 16#16: a request or response carrying an S7 PDU.</summary>
    Variable,

    /// <summary>SD1 16#10 DA SA FC FCS 16#16: no data; the master's poll for a pending response.</summary>
    Fixed,

    /// <summary>SC 16#E5, one character: "received" for a request, "no data yet" for a poll.</summary>
    ShortAcknowledge,

    /// <summary>SD4 16#DC DA SA: a master passing the token. We never send one; seeing one means another master.</summary>
    Token,
}
