using OperatorPanel.Stl;
using OperatorPanel.StlGen.Diagnostics;

namespace OperatorPanel.StlGen.Merge;

/// <summary>The handler's SBR and INT numbers and block names against the user's blocks (each reported at the block's header line).</summary>
internal static class BlockCollisions
{
    public static IEnumerable<MergeDiagnostic> Find(AwlProgram user, HandlerFootprint handler, int subroutines, int interrupts)
    {
        var usedSbr = user.Blocks.Where(b => b.Kind == AwlBlockKind.Subroutine).Select(b => b.Number).ToHashSet();
        var usedInt = user.Blocks.Where(b => b.Kind == AwlBlockKind.InterruptRoutine).Select(b => b.Number).ToHashSet();
        foreach (var block in user.Blocks)
        {
            if (block.Kind == AwlBlockKind.Subroutine && block.Number == handler.Subroutine)
            {
                var free = Enumerable.Range(0, subroutines).Reverse().Where(n => !usedSbr.Contains(n)).Select(n => $" (SBR{n} is free)").FirstOrDefault() ?? string.Empty;
                yield return Error(
                    StlDiagnostics.SubroutineNumberInUse, block,
                    $"SBR{block.Number} is already the user's subroutine {block.Name}; move the handler's subroutine with --sbr N{free}");
            }

            if (block.Kind == AwlBlockKind.InterruptRoutine && block.Number >= handler.FirstInterrupt && block.Number <= handler.LastInterrupt)
            {
                var free = Enumerable.Range(0, interrupts - 2).Reverse().Where(n => !usedInt.Contains(n) && !usedInt.Contains(n + 1) && !usedInt.Contains(n + 2))
                    .Select(n => $" (INT{n}-INT{n + 2} are free)").FirstOrDefault() ?? string.Empty;
                yield return Error(
                    StlDiagnostics.InterruptNumberInUse, block,
                    $"INT{block.Number} is already the user's interrupt routine {block.Name}; the handler needs INT{handler.FirstInterrupt}-INT{handler.LastInterrupt}: move them with --int N{free}");
            }

            if (handler.Names.FirstOrDefault(n => string.Equals(n, block.Name, StringComparison.OrdinalIgnoreCase)) is { } name)
            {
                yield return Error(
                    StlDiagnostics.BlockNameInUse, block,
                    $"block name {block.Name} ({block.DefaultName.Replace("_", string.Empty, StringComparison.Ordinal)}) is also a handler block name ({name}); rename the user's block in Micro/WIN and export again");
            }
        }
    }

    private static MergeDiagnostic Error(string id, AwlBlock block, string message) =>
        new(id, MergeSeverity.Error, block.StartLine, message);
}
