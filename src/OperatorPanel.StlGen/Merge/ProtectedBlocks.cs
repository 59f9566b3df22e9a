using OperatorPanel.Stl;
using OperatorPanel.StlGen.Diagnostics;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// Warns about each password-protected POU of the user's program (<see cref="AwlBlock.IsPasswordProtected"/>): the
/// export holds none of its code, so the handler's port, interrupt events and V bytes cannot be checked against it. A
/// block named as a Siemens library POU that runs Freeport on a fixed port says so when that is the handler's port.
/// Warnings, not refusals: the name is only the library's convention (a user may name a block MBUS_INIT), and the
/// library may be present but switched off (MBUS_INIT with Mode 0 gives the port back to PPI), which the text of a
/// protected block cannot show. docs/awl-exports.md, "A protected POU".
/// </summary>
internal static class ProtectedBlocks
{
    /// <summary>
    /// Library POUs that put a port into Freeport, and that port. The Modbus RTU slave library (MBUS_INIT, MBUS_SLAVE)
    /// works on port 0 only, in Freeport (S7-200 System Manual, Modbus protocol library chapter, ML801761 - page not
    /// read, [U]; a secondary source states it: blog.csdn.net/weixin_39858298/article/details/111274479). The Modbus
    /// master (MBUS_CTRL/MBUS_MSG, _P1 for port 1) and USS (USS_INIT, USS_INIT_P1) libraries: names and ports [U],
    /// from the libraries' naming; the conservative side is to name the collision.
    /// </summary>
    private static readonly Dictionary<string, (string Library, int Port)> Libraries = new(StringComparer.OrdinalIgnoreCase)
    {
        ["MBUS_INIT"] = ("the Modbus RTU slave library", 0),
        ["MBUS_SLAVE"] = ("the Modbus RTU slave library", 0),
        ["MBUS_CTRL"] = ("the Modbus RTU master library", 0),
        ["MBUS_MSG"] = ("the Modbus RTU master library", 0),
        ["MBUS_CTRL_P1"] = ("the Modbus RTU master library", 1),
        ["MBUS_MSG_P1"] = ("the Modbus RTU master library", 1),
        ["USS_INIT"] = ("the USS protocol library", 0),
        ["USS_INIT_P1"] = ("the USS protocol library", 1),
    };

    public static IEnumerable<MergeDiagnostic> Find(AwlProgram user, HandlerFootprint handler, int portCount)
    {
        foreach (var block in user.Blocks.Where(b => b.IsPasswordProtected))
        {
            yield return new MergeDiagnostic(StlDiagnostics.UserBlockWithoutBody, MergeSeverity.Warning, block.StartLine,
                $"{block.Name} ({block.NumberName}, line {block.StartLine}) is password-protected: the export holds none of its code, so the handler's port {handler.Port}, interrupt events {string.Join(", ", handler.Events)} and {handler.VRange} cannot be checked against it; check them yourself, or export it unprotected");
            if (Libraries.TryGetValue(block.Name, out var library) && library.Port == handler.Port)
            {
                var advice = portCount > 1 ? $"put the handler on port {1 - handler.Port} with --plc-port {1 - handler.Port}" : "the CPU has one port: the two cannot run together";
                yield return new MergeDiagnostic(StlDiagnostics.LibraryTakesHandlerPort, MergeSeverity.Warning, block.StartLine,
                    $"{block.Name} ({block.NumberName}) is a block of {library.Library}, which runs Freeport on port {library.Port}, the handler's port: both would set up SMB{handler.PortControlByte} and receive on the port; {advice}, unless the library stays off (its init called with Mode 0)");
            }
        }
    }
}
