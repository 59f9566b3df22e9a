using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// The .awl text of the protocol handler for <paramref name="station"/> on a line of <paramref name="serial"/>'s baud,
/// parity and data bits, or false with why not (e.g. "the handler cannot be generated: STL003 ..."). The App and the
/// CLI pass one that calls StlGen's generator; the Simulator only ever sees the text, as the PLC would (layering:
/// Simulator -> Core, never StlGen).
/// </summary>
public delegate bool StlHandlerSource(
    HandlerConfig station, SerialSettings serial, [NotNullWhen(true)] out string? awlText, [NotNullWhen(false)] out string? error);
